//! The plot: docs/src/tradeoff.svg, error against render time, one panel per scene, with each
//! scene's faster-and-more-accurate front.
//!
//! Both axes are logarithmic, with ticks only at round values (1, 2, 5 × a power of ten, or
//! fewer where those would crowd), the same ranges in every panel so that panels compare. The
//! legend has a panel of its own, so it hides no point. The drawing depends on the results
//! alone (no date, no machine name), so the same JSON always gives the same bytes.
//!
//! This file draws the panels and the legend; [`ticks`] says where the axes' ticks go and how
//! they read, [`labels`] where the labels of the front's points go.

pub mod labels;
pub mod ticks;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::metrics::Row;
use crate::report::scene_front;
use crate::results::Results;
use crate::settings::{SCENES, formula_name};
use labels::{place_labels, text_size};
use ticks::{log_ticks, tick_label};
use whitted::offset::OffsetKind;

/// The picture's size in pixels.
const SIZE: (u32, u32) = (900, 800);
/// Font family of every text.
const FONT: &str = "sans-serif";
/// Nominal font sizes (plotters writes a nominal size s as 0.806·s px into the SVG): the
/// title, the panels' titles, the ticks and the axes' titles, the legend's headings and its
/// text.
const TITLE_FONT: u32 = 24;
const PANEL_FONT: u32 = 20;
const AXIS_FONT: u32 = 17;
const HEADING_FONT: u32 = 17;
const LEGEND_FONT: u32 = 16;
/// At most this many labelled ticks on an axis.
const MAX_TICKS: usize = 8;

/// The colour of each precision and formula pair (Okabe–Ito colours, which stay apart for
/// colour-blind readers): warm for f32, cool for f64, dark for textbook, light for robust.
const COLOURS: [(&str, &str, RGBColor); 4] = [
    ("f32", "textbook", RGBColor(213, 94, 0)),
    ("f32", "robust", RGBColor(230, 159, 0)),
    ("f64", "textbook", RGBColor(0, 114, 178)),
    ("f64", "robust", RGBColor(86, 180, 233)),
];
/// The front's line and labels.
const FRONT: RGBColor = RGBColor(40, 40, 40);
/// The legend's explanations and markers.
const GREY: RGBColor = RGBColor(70, 70, 70);
/// The lines of the grid.
const GRID: RGBColor = RGBColor(215, 215, 215);

/// The scenes' titles in their panels.
const TITLES: [&str; 3] = [
    "showcase",
    "far: the showcase from 1e4 units away",
    "grazing: eye 4 cm above a mirror floor",
];

/// The label of a front point: what sets its place on the time axis and the error axis, the
/// samples per pixel or the recursion depth (the others are at depth 5).
fn front_label(r: &Row) -> String {
    if r.setting.depth != 5 {
        format!("depth {}", r.setting.depth)
    } else {
        format!("{} spp", r.setting.samples)
    }
}

/// A setting's colour.
fn colour(r: &Row) -> RGBColor {
    COLOURS
        .iter()
        .find(|c| c.0 == r.precision && c.1 == formula_name(r.setting.formula))
        .map_or(BLACK, |c| c.2)
}

/// The outline of the fixed-ε marker, a triangle, around pixel (0, 0).
const TRIANGLE: [(i32, i32); 4] = [(0, -6), (6, 4), (-6, 4), (0, -6)];
/// Half the side of the scaled-ε marker, a square.
const SQUARE: i32 = 4;
/// The radius of the error-bound marker, a circle.
const CIRCLE: i32 = 5;

/// Plots `e` as the error axis holds it: errors below the axis (none in practice) sit on it.
fn clamp(e: f64, floor: f64) -> f64 {
    e.max(floor)
}

/// The nominal size of the front's labels (plotters draws a nominal size s as 0.806·s px).
const LABEL_FONT: u32 = 16;

/// The SVG text of the plot.
pub fn svg(results: &Results) -> Result<String, String> {
    let fail = |e: &dyn std::fmt::Display| format!("cannot draw the plot: {e}");
    let rows = &results.rows;
    let ms: Vec<f64> = rows.iter().map(|r| r.seconds * 1e3).collect();
    let finite = |xs: &mut dyn Iterator<Item = f64>| -> (f64, f64) {
        xs.filter(|x| x.is_finite() && *x > 0.0)
            .fold((f64::INFINITY, 0.0), |(a, b), x| (a.min(x), b.max(x)))
    };
    let (t_min, t_max) = finite(&mut ms.iter().copied());
    let (e_min, e_max) = finite(&mut rows.iter().map(|r| r.error.rmse));
    if !(t_min.is_finite() && e_min.is_finite()) {
        return Err(fail(&"no setting has a positive time and error"));
    }
    // room on the left for the labels of the fastest points of the front
    let x_range = t_min / 2.4..t_max * 1.4;
    let y_range = e_min / 1.6..e_max * 1.6;
    let x_ticks = log_ticks(x_range.start, x_range.end, MAX_TICKS);
    let y_ticks = log_ticks(y_range.start, y_range.end, MAX_TICKS);

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(&e))?;
        let body = root
            .titled(
                &format!(
                    "whitted: error against render time ({}×{} pixels, both precisions)",
                    results.width, results.height
                ),
                (FONT, TITLE_FONT),
            )
            .map_err(|e| fail(&e))?;
        let panels = body.split_evenly((2, 2));
        for (scene, area) in panels.iter().take(SCENES.len()).enumerate() {
            let of_scene: Vec<&Row> = rows.iter().filter(|r| r.setting.scene == scene).collect();
            let mut chart = ChartBuilder::on(area)
                .caption(TITLES[scene], (FONT, PANEL_FONT))
                .margin_left(8)
                .margin_right(22)
                .margin_top(4)
                .margin_bottom(8)
                .x_label_area_size(46)
                .y_label_area_size(64)
                .build_cartesian_2d(
                    x_range.clone().log_scale().with_key_points(x_ticks.clone()),
                    y_range.clone().log_scale().with_key_points(y_ticks.clone()),
                )
                .map_err(|e| fail(&e))?;
            chart
                .configure_mesh()
                .bold_line_style(GRID.stroke_width(1))
                .light_line_style(WHITE.stroke_width(0))
                .axis_style(BLACK.stroke_width(1))
                .label_style((FONT, AXIS_FONT))
                .axis_desc_style((FONT, AXIS_FONT))
                .x_label_formatter(&|v| tick_label(*v))
                .y_label_formatter(&|v| tick_label(*v))
                .x_desc(format!("render time (ms, median of {} runs)", results.runs))
                .y_desc("RMSE (8-bit levels)")
                .draw()
                .map_err(|e| fail(&e))?;

            // the front under the markers, so that they stay visible on it
            let floor = y_range.start;
            let front = scene_front(rows, scene);
            chart
                .draw_series(LineSeries::new(
                    front
                        .iter()
                        .map(|r| (r.seconds * 1e3, clamp(r.error.rmse, floor))),
                    FRONT.stroke_width(2),
                ))
                .map_err(|e| fail(&e))?;
            // hollow markers, a shape per offset strategy: where settings coincide, each
            // outline still shows
            let at = |r: &Row| (r.seconds * 1e3, clamp(r.error.rmse, floor));
            let with = |kind: OffsetKind| of_scene.iter().filter(move |r| r.setting.offset == kind);
            chart
                .draw_series(with(OffsetKind::Fixed).map(|r| {
                    EmptyElement::at(at(r))
                        + PathElement::new(TRIANGLE.to_vec(), colour(r).stroke_width(2))
                }))
                .map_err(|e| fail(&e))?;
            chart
                .draw_series(with(OffsetKind::Scaled).map(|r| {
                    EmptyElement::at(at(r))
                        + Rectangle::new(
                            [(-SQUARE, -SQUARE), (SQUARE, SQUARE)],
                            colour(r).stroke_width(2),
                        )
                }))
                .map_err(|e| fail(&e))?;
            chart
                .draw_series(with(OffsetKind::ErrorBound).map(|r| {
                    EmptyElement::at(at(r)) + Circle::new((0, 0), CIRCLE, colour(r).stroke_width(2))
                }))
                .map_err(|e| fail(&e))?;

            // the labels of the front: one per samples-or-depth value, at its fastest point
            let mut labelled: Vec<(&Row, String)> = Vec::new();
            for r in &front {
                let label = front_label(r);
                if labelled.iter().all(|(_, l)| *l != label) {
                    labelled.push((r, label));
                }
            }
            let pixel = |r: &Row| chart.backend_coord(&at(r));
            let (xs, ys) = chart.plotting_area().get_pixel_range();
            let sides = place_labels(
                &labelled
                    .iter()
                    .map(|(r, l)| (pixel(r), text_size(l, LABEL_FONT)))
                    .collect::<Vec<_>>(),
                &of_scene.iter().map(|r| pixel(r)).collect::<Vec<_>>(),
                &front.iter().map(|r| pixel(r)).collect::<Vec<_>>(),
                (xs.start, ys.start, xs.end, ys.end),
            );
            for ((r, label), side) in labelled.iter().zip(sides) {
                let Some(side) = side else { continue };
                let (offset, h, v) = side.anchor();
                let style = TextStyle::from((FONT, LABEL_FONT).into_font())
                    .color(&FRONT)
                    .pos(Pos::new(h, v));
                chart
                    .plotting_area()
                    .draw(&(EmptyElement::at(at(r)) + Text::new(label.clone(), offset, style)))
                    .map_err(|e| fail(&e))?;
            }
        }
        if let Some(area) = panels.get(SCENES.len()) {
            legend(area, results).map_err(|e| fail(&e))?;
        }
        root.present().map_err(|e| fail(&e))?;
    }
    Ok(svg)
}

/// A line of the legend, starting at `at` (its left end, middle height).
fn text(
    s: &str,
    at: (i32, i32),
    size: u32,
    colour: &'static RGBColor,
) -> Text<'static, (i32, i32), String> {
    Text::new(
        s.to_string(),
        at,
        TextStyle::from((FONT, size).into_font())
            .color(colour)
            .pos(Pos::new(HPos::Left, VPos::Center)),
    )
}

/// The legend, in the panel left free by the scenes.
fn legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    results: &Results,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (x0, mut y) = (20, 30);
    let column = 220;
    area.draw(&text(
        "colour: precision, formulas",
        (x0, y),
        HEADING_FONT,
        &BLACK,
    ))?;
    area.draw(&text(
        "shape: offset",
        (x0 + column, y),
        HEADING_FONT,
        &BLACK,
    ))?;
    let shapes = [
        (OffsetKind::Fixed, "fixed ε"),
        (OffsetKind::Scaled, "scaled ε"),
        (OffsetKind::ErrorBound, "error bound"),
    ];
    for (k, (precision, formula, c)) in COLOURS.iter().enumerate() {
        y += 26;
        area.draw(&Rectangle::new(
            [(x0 + 2, y - 6), (x0 + 14, y + 6)],
            c.filled(),
        ))?;
        let name = format!("{precision}, {formula}");
        area.draw(&text(&name, (x0 + 24, y), LEGEND_FONT, &BLACK))?;
        if let Some((offset, name)) = shapes.get(k) {
            let at = (x0 + column + 8, y);
            let style = GREY.stroke_width(2);
            match offset {
                OffsetKind::Fixed => {
                    area.draw(&(EmptyElement::at(at) + PathElement::new(TRIANGLE.to_vec(), style)))?
                }
                OffsetKind::Scaled => area.draw(
                    &(EmptyElement::at(at)
                        + Rectangle::new([(-SQUARE, -SQUARE), (SQUARE, SQUARE)], style)),
                )?,
                OffsetKind::ErrorBound => area.draw(&Circle::new(at, CIRCLE, style))?,
            }
            area.draw(&text(name, (x0 + column + 24, y), LEGEND_FONT, &BLACK))?;
        }
    }
    y += 40;
    area.draw(&PathElement::new(
        vec![(x0, y), (x0 + 30, y)],
        FRONT.stroke_width(2),
    ))?;
    let head = "faster-and-more-accurate front:";
    area.draw(&text(head, (x0 + 40, y), HEADING_FONT, &BLACK))?;
    for line in [
        "no other setting of the scene is both faster and",
        "more accurate. Its labels: samples per pixel (spp),",
        "or the recursion depth at 1 spp (else depth 5)",
    ] {
        y += 22;
        area.draw(&text(line, (x0, y), LEGEND_FONT, &GREY))?;
    }
    y += 18;
    for line in [
        "settings: each formula × offset at 1 spp, depth 5;".to_string(),
        "textbook fixed ε and robust error bound also at".to_string(),
        "4 and 16 spp; robust error bound at depth 1 and 2.".to_string(),
        format!(
            "Reference: f64, robust, error bound, {} spp, depth 12",
            results.reference_samples
        ),
    ] {
        y += 22;
        area.draw(&text(&line, (x0, y), LEGEND_FONT, &GREY))?;
    }
    Ok(())
}
