//! The text parts of a hinge characterisation, kept as numbers until they are written: the
//! closed-form map and the model notes. [`super::characterise`] then costs no heap allocation
//! (a sweep of hinges writes the notes once per file, not once per design); the text is made
//! when the result is serialised or iterated.

use super::profile::{Contour, Profile, AXIAL_BLANK_SLOPE};
use super::solid_effects;
use crate::material::Material;
use serde::ser::{SerializeMap, SerializeSeq};
use serde::{Serialize, Serializer};

/// Most closed forms a family has (the circular notch: four).
const MAX_CLOSED_FORMS: usize = 4;

/// Published closed-form stiffnesses, name → value, in name order (serialised as a JSON
/// object, like a map).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClosedForms {
    entries: [(&'static str, f64); MAX_CLOSED_FORMS],
    len: usize,
}

impl ClosedForms {
    /// The forms `entries` (at most four), put in name order.
    pub(super) fn new(entries: &[(&'static str, f64)]) -> ClosedForms {
        let mut c = ClosedForms {
            entries: [("", 0.0); MAX_CLOSED_FORMS],
            len: entries.len().min(MAX_CLOSED_FORMS),
        };
        c.entries[..c.len].copy_from_slice(&entries[..c.len]);
        c.entries[..c.len].sort_unstable_by(|a, b| a.0.cmp(b.0));
        c
    }

    /// (name, value) pairs in name order.
    pub fn iter(&self) -> impl Iterator<Item = (&'static str, f64)> + '_ {
        self.entries[..self.len].iter().copied()
    }

    /// The values in name order.
    pub fn values(&self) -> impl Iterator<Item = &f64> {
        self.entries[..self.len].iter().map(|(_, v)| v)
    }

    /// The value of the form `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.iter().find(|(k, _)| *k == name).map(|(_, v)| v)
    }

    /// How many forms.
    pub fn len(&self) -> usize {
        self.len
    }

    /// No form applies.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

impl<'a> IntoIterator for &'a ClosedForms {
    type Item = &'a (&'static str, f64);
    type IntoIter = std::slice::Iter<'a, (&'static str, f64)>;
    fn into_iter(self) -> Self::IntoIter {
        self.entries[..self.len].iter()
    }
}

impl Serialize for ClosedForms {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.len))?;
        for (k, v) in self.iter() {
            m.serialize_entry(k, &v)?;
        }
        m.end()
    }
}

// Lines of the model notes without a design-specific number (the JSON form and the text form
// share them).
const BEAM: &str = "bending/shear/axial: exact flexibility of a variable-section Timoshenko beam, Gauss-Legendre on pieces split at profile breakpoints (Cowper shear coefficients)";
const FACE: &str = "compliance referenced to the centre of the loaded blank end face, the other face clamped";
const CALIBRATION: &str = "calibration: converged 10-node tetrahedron solid models (tools/solid_reference.py); circular notches t/R 0.06-0.5 within 2% bending, 4.1% axial; turned necks l/t >= 1 within 3% bending, 5% torsion, 3% axial; leaf within 5%";
const NECK_TORSION: &str =
    "torsion: Saint-Venant (circular waist, no warping); clipped-disk J blended between disk and square";
const VLASOV: &str = "torsion: Vlasov non-uniform torsion FE (Hermite cubics) with the shear strain of the warping (Benscoter; Cowper's kappa), Timoshenko-Goodier J(x), exact rectangle warping constant, warping restrained at both blank end faces; beyond the waist the load-spreading effective thickness at slope 1.6 for J (and, between the rigid blank end faces of this analysis, at least each face's section narrowing back into the blank at 0.4; a mechanism's hinge element, whose ends are in continuous material, does without it), for the warping constant at 1/2 in the notch and 1.0 in the blank (the three slopes fitted); wide waists warp in the plate mode (Gamma = w^3 t^3/144, modulus E/(1-nu^2)), compact waists (w/t < 1.7) carry no warping restraint (CalculiX solid models: see the README validation table)";
const NO_SPREAD: &str = "load spreading: none needed (the contour never widens faster than slope 1/2)";

/// The idealisations and models of a characterisation, as the numbers their text quotes
/// (serialised as a JSON array of strings; [`ModelNotes::lines`] gives the text).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelNotes {
    /// A turned neck (circular waist) rather than a flat notch.
    neck: bool,
    /// Notch stress-concentration factor.
    kt: f64,
    /// Load spreading: (slope, from |x|, reach), mm.
    spread: Option<(f64, f64, f64)>,
    /// Short-notch factor G and plane-strain factor P.
    g: f64,
    p: f64,
}

impl ModelNotes {
    /// The notes of `profile` in `material` with notch factor `kt`.
    pub(super) fn new(profile: &Profile, material: &Material, kt: f64) -> ModelNotes {
        ModelNotes {
            neck: matches!(profile.contour, Contour::SphericalNeck { .. }),
            kt,
            spread: profile.spread.map(|sp| (sp.slope, sp.from, profile.spread_reach())),
            g: solid_effects::short_notch_factor(profile) * solid_effects::fillet_factor(profile),
            p: solid_effects::plane_strain_factor(profile, material.nu),
        }
    }

    /// The numbers the notes quote, as a result field.
    pub fn calibration(&self) -> Calibration {
        Calibration {
            short_notch_g: self.g,
            plane_strain_p: self.p,
            load_spreading: self
                .spread
                .map(|(slope, from_mm, to_mm)| LoadSpreading { slope, from_mm, to_mm }),
        }
    }

    /// The notes without their numbers (the JSON form: see the `Serialize` impl).
    pub fn invariant_lines(&self) -> &'static [&'static str] {
        const MODULUS: &str = "compliant-axis bending modulus of the notch region E*P/G, axial modulus E*(1 + 0.6 (P - 1))/G (solid-calibrated): short-notch G and plane-strain P in calibration (corner fillets: G with rho = R on the fillet arcs only; the flat takes P without G); in the blank's load-spreading zone the same plane-strain restraint with the local effective thickness as its free edge layer, E*P_b and E*(1 + 0.6 (P_b - 1)), P_b = 1 + (P - 1)(w - s)/(w - t) for s < w (no fitted number)";
        const NECK_STRESS: &str = "stress: 32M/(pi t^3) at the waist x Kt = stress_concentration (shoulder-fillet Kt = 1 + 0.041 sqrt(t/R), fitted to solid models within 2%)";
        const NOTCH_STRESS: &str = "stress: 6M/(w t^2) at the waist x stress_concentration (Kt = (1 + t/(2R))^(9/20) after Peterson / Tian et al. 2010, divided by sqrt(P) for the plane-strain waist; corner fillet: Kt = 1 + 0.24 t/(2R), times 1 - 0.71 (P - 1) and the long-leaf root amplification; converged CalculiX solid models: within 4% for circular and corner-filleted notches)";
        const SPREAD: &str = "load spreading (solid-calibrated): effective half-size grows at calibration.load_spreading.slope from |x| = from_mm to to_mm; for the axial load at 0.56 beyond the notch (fitted)";
        match (self.neck, self.spread.is_some()) {
            (true, true) => &[BEAM, FACE, NECK_TORSION, NECK_STRESS, SPREAD, MODULUS, CALIBRATION],
            (true, false) => &[BEAM, FACE, NECK_TORSION, NECK_STRESS, NO_SPREAD, MODULUS, CALIBRATION],
            (false, true) => &[BEAM, FACE, VLASOV, NOTCH_STRESS, SPREAD, MODULUS, CALIBRATION],
            (false, false) => &[BEAM, FACE, VLASOV, NOTCH_STRESS, NO_SPREAD, MODULUS, CALIBRATION],
        }
    }

    /// The notes as text with their numbers, one line each (the Markdown report's form).
    pub fn lines(&self) -> Vec<String> {
        let kt = self.kt;
        let mut v = vec![BEAM.to_string(), FACE.to_string()];
        if self.neck {
            v.push(NECK_TORSION.into());
            v.push(format!("stress: 32M/(pi t^3) at the waist x Kt = {kt:.4} (shoulder-fillet Kt = 1 + 0.041 sqrt(t/R), fitted to solid models within 2%)"));
        } else {
            v.push(VLASOV.into());
            v.push(format!("stress: 6M/(w t^2) at the waist x {kt:.4} (Kt = (1 + t/(2R))^(9/20) after Peterson / Tian et al. 2010, divided by sqrt(P) for the plane-strain waist; corner fillet: Kt = 1 + 0.24 t/(2R), times 1 - 0.71 (P - 1) and the long-leaf root amplification; converged CalculiX solid models: within 4% for circular and corner-filleted notches)"));
        }
        match self.spread {
            Some((slope, from, reach)) => v.push(format!(
                "load spreading (solid-calibrated): effective half-size grows at slope {slope} from |x| = {from:.3} mm to {reach:.3} mm; for the axial load at {AXIAL_BLANK_SLOPE} beyond the notch (fitted)"
            )),
            None => v.push(NO_SPREAD.into()),
        }
        let (g, p) = (self.g, self.p);
        v.push(format!(
            "compliant-axis bending modulus of the notch region E*P/G, axial modulus E*(1 + 0.6 (P - 1))/G (solid-calibrated): short-notch G = {g:.4}, plane-strain P = {p:.4}; in the blank's load-spreading zone the same plane-strain restraint with the local effective thickness as its free edge layer, E*P_b and E*(1 + 0.6 (P_b - 1)), P_b = 1 + (P - 1)(w - s)/(w - t) for s < w (no fitted number)"
        ));
        v.push(CALIBRATION.into());
        v
    }
}

impl IntoIterator for &ModelNotes {
    type Item = String;
    type IntoIter = std::vec::IntoIter<String>;
    fn into_iter(self) -> Self::IntoIter {
        self.lines().into_iter()
    }
}

/// The JSON form of the notes: the same lines with every design-specific number left out (they
/// are the result's `stress_concentration` and `calibration`), so that every design of one hinge
/// family has the same notes — a sweep writes them once per file — and writing them allocates
/// nothing.
impl Serialize for ModelNotes {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let lines = self.invariant_lines();
        let mut seq = s.serialize_seq(Some(lines.len()))?;
        for l in lines {
            seq.serialize_element(l)?;
        }
        seq.end()
    }
}

/// The solid-calibrated factors a characterisation used (the numbers the model notes refer to).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Calibration {
    /// Short-notch factor G of the compliant-axis bending modulus E·P/G (dimensionless; for a
    /// corner-filleted hinge that of the fillet arcs, ρ = R: the flat has E·P).
    pub short_notch_g: f64,
    /// Plane-strain factor P of the compliant-axis bending modulus E·P/G (dimensionless).
    pub plane_strain_p: f64,
    /// Load spreading into the blank (absent: none needed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_spreading: Option<LoadSpreading>,
}

/// Where the effective (load-carrying) half-size of the blank grows linearly.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadSpreading {
    /// Growth of the effective half-size per unit length (dimensionless).
    pub slope: f64,
    /// |x| from which it grows, mm.
    pub from_mm: f64,
    /// |x| at which it reaches the blank's half-size, mm.
    pub to_mm: f64,
}
