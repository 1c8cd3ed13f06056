//! The plot: docs/tradeoff.svg, error against render time.

use std::path::Path;

use crate::metrics::Row;
use crate::settings::formula_name;

/// Error (RMSE, 8-bit levels) against render time, one series per precision, log-log.
pub fn plot(rows: &[Row], path: &Path) -> Result<(), String> {
    use plotters::prelude::*;
    let fail = |e: String| format!("cannot draw {}: {e}", path.display());
    // drawn into memory, then written atomically like every other output
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(e.to_string()))?;
        let floor = 0.01;
        let t_min = rows
            .iter()
            .map(|r| r.seconds * 1e3)
            .fold(f64::INFINITY, f64::min);
        let t_max = rows.iter().map(|r| r.seconds * 1e3).fold(0.0, f64::max);
        let e_max = rows.iter().map(|r| r.error.rmse).fold(floor, f64::max);
        let mut chart = ChartBuilder::on(&root)
            .caption("whitted: error against render time", ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (t_min * 0.8..t_max * 1.25).log_scale(),
                (floor..e_max * 1.5).log_scale(),
            )
            .map_err(|e| fail(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc("render time (ms, median)")
            .y_desc("RMSE against the reference (8-bit levels)")
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        let styles = [
            ("f32", "textbook", RGBColor(214, 39, 40)),
            ("f32", "robust", RGBColor(255, 152, 150)),
            ("f64", "textbook", RGBColor(31, 119, 180)),
            ("f64", "robust", RGBColor(140, 190, 230)),
        ];
        for (precision, formula, color) in styles {
            let points: Vec<(f64, f64, usize)> = rows
                .iter()
                .filter(|r| r.precision == precision && formula_name(r.setting.formula) == formula)
                .map(|r| (r.seconds * 1e3, r.error.rmse.max(floor), r.setting.scene))
                .collect();
            chart
                .draw_series(points.iter().map(|&(t, e, scene)| {
                    let style = color.filled();
                    match scene {
                        0 => Circle::new((t, e), 5, style).into_dyn(),
                        1 => TriangleMarker::new((t, e), 6, style).into_dyn(),
                        _ => Cross::new((t, e), 5, color.stroke_width(2)).into_dyn(),
                    }
                }))
                .map_err(|e| fail(e.to_string()))?
                .label(format!("{precision} {formula}"))
                .legend(move |(x, y)| Circle::new((x, y), 5, color.filled()));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(|e| fail(e.to_string()))?;
        root.draw(&Text::new(
            "● showcase   ▲ far   × grazing",
            (80, 570),
            ("sans-serif", 15),
        ))
        .map_err(|e| fail(e.to_string()))?;
        root.present().map_err(|e| fail(e.to_string()))?;
    }
    whitted::output::write_file(path, svg.as_bytes()).map_err(|e| e.to_string())
}
