//! Material given by built-in name or as an object.

use super::error::{check, CaseError};
use crate::material::Material;
use serde::{Deserialize, Deserializer};

/// A built-in material by name (`"Al7075"`, `"nylon66"`, `"steel"`, `"Ti6Al4V"`; case-insensitive) or an
/// object `{"E", "nu", "density", "yield", "allowable"}`.
#[derive(Debug, Clone, PartialEq, schemars::JsonSchema)]
#[serde(untagged)]
pub enum MaterialSpec {
    /// A built-in material name (case-insensitive): Al7075 (aluminium 7075-T6), nylon66, steel,
    /// Ti6Al4V (titanium grade 5, annealed).
    #[schemars(schema_with = "builtin_name_schema")]
    Name(String),
    /// Explicit properties (mm–N–MPa–tonne).
    Custom(Material),
}

/// The built-in names: an `enum` of their usual spelling (for editors) or any letter case.
fn builtin_name_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    let any_case: Vec<String> = Material::BUILTIN_NAMES
        .iter()
        .map(|n| {
            n.chars()
                .map(|c| {
                    if c.is_ascii_alphabetic() {
                        format!("[{}{}]", c.to_ascii_uppercase(), c.to_ascii_lowercase())
                    } else {
                        c.to_string()
                    }
                })
                .collect()
        })
        .collect();
    schemars::json_schema!({
        "type": "string",
        "anyOf": [
            {"enum": Material::BUILTIN_NAMES},
            {"pattern": format!("^({})$", any_case.join("|"))}
        ]
    })
}

impl Default for MaterialSpec {
    fn default() -> Self {
        MaterialSpec::Name("Al7075".into())
    }
}

impl<'de> Deserialize<'de> for MaterialSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let v = serde_json::Value::deserialize(d)?;
        match v {
            serde_json::Value::String(s) => Ok(MaterialSpec::Name(s)),
            serde_json::Value::Object(_) => {
                let m: Material = serde_path_to_error::deserialize(v).map_err(|e| {
                    let p = e.path().to_string();
                    D::Error::custom(format!("in material object at `{p}`: {}", e.inner()))
                })?;
                Ok(MaterialSpec::Custom(m))
            }
            other => Err(D::Error::custom(format!(
                "invalid material {other}: expected a built-in name ({}) or an object {{\"E\", \"nu\", \"density\", \"yield\", \"allowable\"}}",
                Material::BUILTIN_NAMES.join(", ")
            ))),
        }
    }
}

impl MaterialSpec {
    /// Resolves and validates the material; `path` is its JSON path.
    pub fn resolve(&self, path: &str) -> Result<Material, CaseError> {
        let m = match self {
            MaterialSpec::Name(n) => Material::builtin(n).ok_or_else(|| {
                CaseError::value(
                    path,
                    format!("\"{n}\""),
                    format!(
                        "unknown material; built-in names are {}",
                        Material::BUILTIN_NAMES.join(", ")
                    ),
                )
            })?,
            MaterialSpec::Custom(m) => *m,
        };
        check::positive(format_args!("{path}.E"), m.e, "MPa")?;
        if !(m.nu > -1.0 && m.nu < 0.5) {
            return Err(CaseError::value(
                format!("{path}.nu"),
                m.nu,
                "Poisson's ratio must lie in (−1, 0.5)",
            ));
        }
        check::non_negative(format_args!("{path}.density"), m.density, "t/mm³")?;
        if m.yield_strength.is_nan() || m.yield_strength <= 0.0 {
            return Err(CaseError::value(
                format!("{path}.yield"),
                m.yield_strength,
                "must be positive (MPa)",
            ));
        }
        if m.allowable.is_nan() || m.allowable <= 0.0 {
            return Err(CaseError::value(
                format!("{path}.allowable"),
                m.allowable,
                "must be positive (MPa)",
            ));
        }
        Ok(m)
    }
}

/// Plausible densities of structural solids in the case-file units, t/mm³: 1e-10 (100 kg/m³,
/// rigid foams) … 3e-8 (30 000 kg/m³, above the densest metals, 22 600 kg/m³).
pub const DENSITY_RANGE: (f64, f64) = (1e-10, 3e-8);

/// A warning when a material's density (t/mm³) is outside [`DENSITY_RANGE`] — typically a
/// density typed in kg/m³ or g/cm³, which makes natural frequencies 10⁶× or 3·10⁴× too low
/// (f ∝ 1/√ρ). `None` for plausible densities and for 0 (massless on purpose). `at` is the
/// material's place in the case file, e.g. `materials.steel`.
pub fn density_warning(at: &str, m: &Material) -> Option<String> {
    let rho = m.density;
    let (lo, hi) = DENSITY_RANGE;
    if rho == 0.0 || (lo..=hi).contains(&rho) {
        return None;
    }
    let hint = if (100.0..=30_000.0).contains(&rho) {
        format!(
            " — it looks like kg/m³: in t/mm³ it is {:.3e} (kg/m³ × 1e-12), and as given the natural frequencies come out 10⁶× too low",
            rho * 1e-12
        )
    } else if (0.1..=30.0).contains(&rho) {
        format!(
            " — it looks like g/cm³: in t/mm³ it is {:.3e} (g/cm³ × 1e-9), and as given the natural frequencies come out {:.0}× too low",
            rho * 1e-9,
            1e9f64.sqrt()
        )
    } else {
        String::new()
    };
    Some(format!(
        "{at}.density = {rho:e} t/mm³ is outside the plausible range {lo:e} … {hi:e} t/mm³ (100 … 30 000 kg/m³; steel 7.85e-9){hint}; masses, self-weight and natural frequencies follow it (f ∝ 1/√density)"
    ))
}

/// Plausible Young's moduli of the solids flexures are made of, MPa: 100 (the stiffest
/// elastomers and soft polyethylene, LDPE ≈ 200) … 1.2e6 (diamond, 1.05e6, the stiffest solid).
pub const MODULUS_RANGE: (f64, f64) = (100.0, 1.2e6);

/// A warning when a material's Young's modulus (MPa) is outside [`MODULUS_RANGE`] — typically
/// E typed in GPa (72 for aluminium: 1000× too soft), in Pa (72e9: 10⁶× too stiff) or in psi
/// (10.4e6 for aluminium: 145× too stiff); displacements and rotations under given forces
/// scale as 1/E. `None` for plausible moduli. `at` as for [`density_warning`].
pub fn modulus_warning(at: &str, m: &Material) -> Option<String> {
    let e = m.e;
    let (lo, hi) = MODULUS_RANGE;
    if (lo..=hi).contains(&e) {
        return None;
    }
    let hint = if (0.1..lo).contains(&e) {
        format!(" — it looks like GPa: in MPa it is {} (GPa × 1000), and as given the displacements come out 1000× too large", plain(e * 1e3))
    } else if (1e8..=1.2e12).contains(&e) {
        format!(
            " — it looks like Pa: in MPa it is {} (Pa × 1e-6), and as given the displacements come out 10⁶× too small",
            plain(e * 1e-6)
        )
    } else if (1.45e6..1e8).contains(&e) {
        format!(" — it looks like psi: in MPa it is {} (psi × 6.894757e-3), and as given the displacements come out 145× too small", plain(e * 6.894757e-3))
    } else {
        String::new()
    };
    let stand_in = if e > hi {
        "; a stand-in for a rigid part is exact as a `rigid` element"
    } else {
        ""
    };
    Some(format!(
        "{at}.E = {} MPa is outside the plausible range {} … {:e} MPa of structural solids (nylon 2800, aluminium 72000, steel 210000 MPa){hint}; displacements and rotations under given forces scale as 1/E{}",
        plain(e),
        plain(lo),
        hi,
        if e < lo {
            format!(" (an elastomer softer than {} MPa is possible: then ignore this)", plain(lo))
        } else {
            stand_in.to_string()
        }
    ))
}

/// The unit-slip warnings of a material (Young's modulus, density) at `at` (e.g. `material`,
/// `materials.steel`): one place for every analysis kind that takes a material.
pub fn plausibility_warnings(at: &str, m: &Material) -> Vec<String> {
    modulus_warning(at, m)
        .into_iter()
        .chain(density_warning(at, m))
        .collect()
}

/// A number as typed: plain below 1e7, else in exponent notation.
fn plain(v: f64) -> String {
    if v.abs() < 1e7 {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}
