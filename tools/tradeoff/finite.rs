//! Serde for an f64 that may not be finite: JSON has no NaN or ∞, so those are written as
//! `null` and read back as NaN. Fields use it as `#[serde(with = "crate::finite")]`.

use serde::{Deserialize, Deserializer, Serializer};

/// Writes `x`, or `null` if it is not finite.
pub fn serialize<S: Serializer>(x: &f64, serializer: S) -> Result<S::Ok, S::Error> {
    if x.is_finite() {
        serializer.serialize_f64(*x)
    } else {
        serializer.serialize_none()
    }
}

/// Reads a number, or NaN for `null`.
pub fn deserialize<'de, D: Deserializer<'de>>(deserializer: D) -> Result<f64, D::Error> {
    Ok(Option::<f64>::deserialize(deserializer)?.unwrap_or(f64::NAN))
}
