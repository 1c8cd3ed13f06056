//! A worker's `planet.tsv`: everything it measures on the planets, written a line a
//! measurement by [`measure_all`], and read back by the coordinator as [`Measured`].

use std::fmt::Write as _;
use std::path::Path;

use super::errors::{HitError, acne, costs, hit_errors};
use super::fixes::Method;
use super::setup::{ANGLES, Planet, RADII, samples};

/// Everything a worker measures on the planets, as the lines of `planet.tsv`:
/// `hit R angle method both disagree surface along distance`, `acne R fixed scaled
/// error-bound push anchored-fixed` and `cost method ns`.
pub fn measure_all() -> String {
    let samples = samples();
    let planets: Vec<Planet> = RADII.iter().map(|&r| Planet::new(r)).collect();
    let mut out = String::new();
    for planet in &planets {
        for method in Method::ALL {
            for (angle, e) in hit_errors(planet, &samples, method).iter().enumerate() {
                let _ = writeln!(
                    out,
                    "hit\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}",
                    planet.radius,
                    ANGLES[angle],
                    method.name(),
                    e.both,
                    e.disagree,
                    e.surface,
                    e.along,
                    e.distance
                );
            }
        }
        let ([fixed, scaled, bound], push, anchored) = acne(planet, &samples);
        let _ = writeln!(
            out,
            "acne\t{}\t{fixed}\t{scaled}\t{bound}\t{push}\t{anchored}",
            planet.radius
        );
    }
    for (method, ns) in costs(&planets, &samples) {
        let _ = writeln!(out, "cost\t{}\t{ns}", method.name());
    }
    out
}

/// One worker's planet measurements, read back from `planet.tsv`.
#[derive(Default)]
pub struct Measured {
    /// (R, angle, method) and the errors.
    pub hits: Vec<(f64, f64, String, HitError)>,
    /// R, the acne share under fixed, scaled and error-bound, the error-bound push, and the
    /// share under fixed ε with the anchored fix.
    pub acne: Vec<(f64, [f64; 3], f64, f64)>,
    /// Method and ns per ray.
    pub costs: Vec<(String, f64)>,
}

impl Measured {
    /// The lines of a worker's `planet.tsv`.
    pub fn lines(dir: &Path) -> Result<Vec<String>, String> {
        let path = dir.join("planet.tsv");
        let text = std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        Ok(text.lines().map(str::to_string).collect())
    }

    /// Parses the lines of a worker's `planet.tsv` (`origin` names them in errors).
    pub fn parse(lines: &[String], origin: &str) -> Result<Self, String> {
        let bad = |line: &str| format!("{origin}: cannot read `{line}`");
        let mut m = Measured::default();
        for line in lines {
            let f: Vec<&str> = line.split('\t').collect();
            let num = |i: usize| f.get(i).and_then(|s| s.parse::<f64>().ok());
            match f[0] {
                "hit" => {
                    let e = HitError {
                        both: num(4).ok_or_else(|| bad(line))? as usize,
                        disagree: num(5).ok_or_else(|| bad(line))? as usize,
                        surface: num(6).ok_or_else(|| bad(line))?,
                        along: num(7).ok_or_else(|| bad(line))?,
                        distance: num(8).ok_or_else(|| bad(line))?,
                    };
                    let (r, a) = (
                        num(1).ok_or_else(|| bad(line))?,
                        num(2).ok_or_else(|| bad(line))?,
                    );
                    m.hits.push((r, a, f[3].to_string(), e));
                }
                "acne" => {
                    let v: Option<Vec<f64>> = (1..7).map(num).collect();
                    let v = v.ok_or_else(|| bad(line))?;
                    m.acne.push((v[0], [v[1], v[2], v[3]], v[4], v[5]));
                }
                "cost" => {
                    let ns = num(2).ok_or_else(|| bad(line))?;
                    m.costs.push((f[1].to_string(), ns));
                }
                _ => return Err(bad(line)),
            }
        }
        Ok(m)
    }

    /// The errors of `method` at radius `r` and angle `a`.
    pub fn hit(&self, r: f64, a: f64, method: Method) -> Option<&HitError> {
        self.hits
            .iter()
            .find(|h| h.0 == r && h.1 == a && h.2 == method.name())
            .map(|h| &h.3)
    }

    /// The errors of `method` at radius `r`, worst over the angles (disagreements summed).
    pub fn worst(&self, r: f64, method: Method) -> HitError {
        let mut w = HitError::default();
        for h in self
            .hits
            .iter()
            .filter(|h| h.0 == r && h.2 == method.name())
        {
            w.both += h.3.both;
            w.disagree += h.3.disagree;
            w.surface = w.surface.max(h.3.surface);
            w.along = w.along.max(h.3.along);
        }
        w
    }

    /// ns per ray of `method`.
    pub fn cost(&self, method: Method) -> f64 {
        self.costs
            .iter()
            .find(|c| c.0 == method.name())
            .map_or(f64::NAN, |c| c.1)
    }
}
