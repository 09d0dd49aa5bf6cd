//! Flexure hinges: profiles, stiffness, stress, published closed forms.
//!
//! # Model
//!
//! Each hinge is a straight beam along x (x = 0 at the hinge centre) whose cross-section
//! varies with x: the notch region of the family's contour, then `blank_length` of the full
//! blank section on each side. Its 6×6 compliance between the two blank end faces (one
//! clamped, the load applied at the centre of the other through a rigid face, as in the
//! Ruiz et al. ANSYS set-up) is the exact flexibility of a variable-section Timoshenko beam,
//! C = ∫ Bᵀ D(x) B dx, integrated by Gauss–Legendre on pieces split at every profile breakpoint
//! ([`integrate`]). Why a beam and not a solid model: for the notch geometries of the hinge families the
//! beam idealisation is within a few per cent of converged solid FEM (98.2 vs 98.37 N·m/rad for
//! the Ruiz et al. notch), costs microseconds, and gives a flexibility that the stage builder can
//! turn into beam elements ([`segment_compliance`]). Its known gaps are handled explicitly:
//!
//! * **Torsion** of rectangular notches: Saint-Venant is far too soft because the blanks
//!   restrain warping; k_torsion comes from a warping-torsion FE ([`torsion`]) on the
//!   geometric section in the notch and the load-spreading effective section in the blank:
//!   Vlasov's model with Benscoter's shear strain of the warping, plate-mode warping of wide
//!   waists and torsional spreading at slope 1.6, measured against CalculiX solid models
//!   ([`torsion::solid_torsion_stiffness`]). The turned
//!   neck has a circular waist (no warping) and uses plain ∫1/GJ.
//! * **Three-dimensional effects**, calibrated against converged quadratic-tetrahedron solid
//!   models (`tools/solid_reference.py`, tests/hinge_solid_reference.rs): load spreading out of
//!   the waist into flanks, shoulders and blank at slope 1/2 ([`Profile::spread`]; this alone
//!   took turned necks from +19 % to ±3 % axial and from +12 % to ±2 % bending), the short-notch
//!   factor G and the plane-strain factor P of a wide waist on the compliant-axis bending
//!   modulus of the notch ([`solid_effects`]). Circular notches t/R 0.06–0.5, w/t 0.5–20:
//!   bending within 2 %, axial within 4.4 % of the solid models.
//! * **Stress**: beam stress at the waist times a notch stress-concentration factor, divided by
//!   √P for wide waists ([`stress`]).
//!
//! Units: mm, N, MPa; rotations in radians inside, degrees only in `max_rotation_deg`.

pub mod calibration;
pub mod chain;
pub mod closed_form;
pub mod contour;
pub mod damping;
pub mod element;
pub mod error;
pub mod integrate;
pub mod notes;
pub mod pieces;
pub mod profile;
pub mod section;
pub mod solid_effects;
pub mod spec;
pub mod stress;
pub mod tangent;
pub mod torsion;

use nalgebra::Matrix6;
use serde::Serialize;

use crate::material::Material;
pub use chain::{chain_compliances, split_flex, split_flex_with, NONLINEAR_SEGMENTS};
pub use element::{
    flex_chain, flex_region, hinge_element, hinge_peak_stress, spreading_region, HingeRegion, PeakStressTable,
};
pub use error::HingeError;
use integrate::{flex_integrals, flex_integrals_with_notch, BlankRestraint, Moduli, Quadrature};
pub use notes::{Calibration, ClosedForms, LoadSpreading, ModelNotes};
pub use profile::{Contour, EndFaces, Profile};
pub use section::Section;
pub use spec::HingeSpec;

/// Stiffness and stress of one configuration (hinge in its blank, or notch alone).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stiffness {
    /// Compliant-axis rotational stiffness M_y/θ_y, N·mm/rad.
    pub k_bend: f64,
    /// Stiff-axis rotational stiffness M_z/θ_z, N·mm/rad.
    pub k_bend_off: f64,
    /// Torsional stiffness M_x/θ_x, N·mm/rad.
    pub k_torsion: f64,
    /// Axial stiffness F_x/u_x, N/mm.
    pub k_axial: f64,
    /// 6×6 compliance at the free end face centre, rows/cols (ux, uy, uz, rx, ry, rz);
    /// units mm/N, 1/N, rad/(N·mm).
    pub compliance: [[f64; 6]; 6],
    /// Peak stress per unit compliant-axis moment, MPa per N·mm.
    pub stress_per_moment: f64,
    /// Compliant-axis rotation at which the peak stress reaches the material's allowable, deg
    /// (`null`: the material has no allowable stress).
    #[serde(serialize_with = "crate::report::numbers::unbounded_as_null")]
    pub max_rotation_deg: f64,
    /// Saint-Venant (free-warping) torsional stiffness, N·mm/rad, for comparison.
    pub k_torsion_saint_venant: f64,
}

/// Result of [`characterise`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HingeResult {
    /// Hinge in its blank: between the two blank end faces.
    #[serde(flatten)]
    pub hinge: Stiffness,
    /// Published closed forms, name → compliant-axis stiffness of the notch alone, N·mm/rad.
    pub closed_form: ClosedForms,
    /// The same quantities for the notch alone (blank_length = 0).
    pub notch_only: Stiffness,
    /// Notch stress-concentration factor applied to the beam stress.
    pub stress_concentration: f64,
    /// The solid-calibrated factors used (the numbers the model notes refer to).
    pub calibration: Calibration,
    /// Idealisations and models used: JSON without design-specific numbers (those are
    /// `stress_concentration` and `calibration`); [`ModelNotes::lines`] quotes them.
    pub model: ModelNotes,
}

/// Checks the material constants the hinge model needs.
fn check_material(m: &Material) -> Result<(), HingeError> {
    if !(m.e.is_finite() && m.e > 0.0) {
        return Err(HingeError::InvalidMaterial {
            param: "E",
            value: m.e,
            allowed: "must be a finite number > 0".into(),
        });
    }
    if !(m.nu > -1.0 && m.nu < 0.5) {
        return Err(HingeError::InvalidMaterial {
            param: "nu",
            value: m.nu,
            allowed: "must be in (-1, 0.5)".into(),
        });
    }
    if m.allowable.is_nan() || m.allowable <= 0.0 {
        return Err(HingeError::InvalidMaterial {
            param: "allowable",
            value: m.allowable,
            allowed: "must be > 0".into(),
        });
    }
    Ok(())
}

fn moduli(profile: &Profile, m: &Material) -> Moduli {
    let (p, g) = (
        solid_effects::plane_strain_factor(profile, m.nu),
        solid_effects::short_notch_factor(profile),
    );
    let (factor, axial) = (p / g, solid_effects::axial_restraint(p));
    Moduli {
        e: m.e,
        e_bend: m.e * factor,
        g: m.shear_modulus(),
        nu: m.nu,
        shear: true,
        notch_half: profile.half_notch,
        e_bend_fillet: m.e * factor / solid_effects::fillet_factor(profile),
        fillet_from: solid_effects::fillet_from(profile),
        e_axial: m.e * axial / g,
        e_axial_fillet: m.e * axial / (g * solid_effects::fillet_factor(profile)),
        blank: BlankRestraint {
            restraint: solid_effects::plane_strain_restraint(profile, m.nu),
            w: profile.w,
            h: profile.h,
        },
    }
}

/// 6×6 compliance of the segment [x0, x1] of a hinge profile, clamped at x0 and loaded at the
/// centre of the section at x1 (Timoshenko flexibility, Saint-Venant torsion). The stage builder
/// uses it to turn hinge segments into flexibility-based beam elements.
pub fn segment_compliance(profile: &Profile, material: &Material, x0: f64, x1: f64) -> Matrix6<f64> {
    flex_integrals(profile, &moduli(profile, material), x0, x1, Quadrature::default()).compliance()
}

fn stiffness_of(profile: &Profile, material: &Material, kt: f64) -> Stiffness {
    let half = profile.half_length();
    stiffness_from(
        profile,
        material,
        kt,
        segment_compliance(profile, material, -half, half),
    )
}

/// The stiffness of `profile` from its Timoshenko compliance `c` (Saint-Venant torsion), with
/// the torsion replaced by the warping-restrained one for rectangular sections.
fn stiffness_from(profile: &Profile, material: &Material, kt: f64, c: Matrix6<f64>) -> Stiffness {
    let k_torsion = match profile.contour {
        Contour::SphericalNeck { .. } => 1.0 / c[(3, 3)],
        _ => torsion::solid_torsion_stiffness(profile, material.e, material.nu),
    };
    with_torsion(profile, material, kt, c, k_torsion)
}

/// The stiffness of `profile` from its Timoshenko compliance `c` (Saint-Venant torsion) and its
/// torsional stiffness `k_torsion`.
fn with_torsion(profile: &Profile, material: &Material, kt: f64, c: Matrix6<f64>, k_torsion: f64) -> Stiffness {
    let k_sv = 1.0 / c[(3, 3)];
    let mut cm = c;
    cm[(3, 3)] = 1.0 / k_torsion;
    let k_bend = 1.0 / cm[(4, 4)];
    let spm = kt * stress::nominal_stress_per_moment(profile);
    let max_rot = (material.allowable / spm / k_bend).to_degrees();
    let mut compliance = [[0.0; 6]; 6];
    for (i, row) in compliance.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = cm[(i, j)];
        }
    }
    Stiffness {
        k_bend,
        k_bend_off: 1.0 / cm[(5, 5)],
        k_torsion,
        k_axial: 1.0 / cm[(0, 0)],
        compliance,
        stress_per_moment: spm,
        max_rotation_deg: max_rot,
        k_torsion_saint_venant: k_sv,
    }
}

/// Stiffness of a hinge in its blank and of its notch alone (`notch`: the same profile with no
/// blank), the bending, shear and axial flexibilities of both from one pass over the sections
/// ([`integrate::flex_integrals_with_notch`]).
fn stiffness_pair(profile: &Profile, notch: &Profile, material: &Material, kt: f64) -> (Stiffness, Stiffness) {
    let (whole, alone) = flex_integrals_with_notch(profile, &moduli(profile, material), Quadrature::default());
    let (c, cn) = (whole.compliance(), alone.compliance());
    let (kt_whole, kt_notch) = match profile.contour {
        Contour::SphericalNeck { .. } => (1.0 / c[(3, 3)], 1.0 / cn[(3, 3)]),
        _ => torsion::solid_torsion_pair(profile, notch, material.e, material.nu),
    };
    (
        with_torsion(profile, material, kt, c, kt_whole),
        with_torsion(notch, material, kt, cn, kt_notch),
    )
}

/// Characterises a hinge: stiffness, compliance, stress, closed forms, for the hinge in its
/// blank and for the notch alone.
///
/// Cost: the flexibility integrals of both configurations share one pass over the quadrature
/// points; each needs its own warping-torsion solve. A caller that needs only the hinge in its
/// blank calls [`profile_stiffness`] (half the work, no text).
pub fn characterise(spec: &HingeSpec, material: &Material) -> Result<HingeResult, HingeError> {
    check_material(material)?;
    // The hinge in its blank: clamped and loaded through rigid end faces.
    let profile = spec.profile()?.with_rigid_end_faces();
    let notch = spec.profile_with_blank(Some(0.0))?;
    let kt = stress::stress_factor(&profile, material.nu);
    let (hinge, notch_only) = stiffness_pair(&profile, &notch, material, kt);
    let closed = closed_forms(spec, material.e);
    let model = ModelNotes::new(&profile, material, kt);
    Ok(HingeResult {
        hinge,
        closed_form: closed,
        notch_only,
        stress_concentration: kt,
        calibration: model.calibration(),
        model,
    })
}

/// Stiffness, compliance and stress of a validated profile as it stands (its own blank).
pub fn profile_stiffness(profile: &Profile, material: &Material) -> Result<Stiffness, HingeError> {
    check_material(material)?;
    let kt = stress::stress_factor(profile, material.nu);
    Ok(stiffness_of(profile, material, kt))
}

/// Closed-form compliant-axis stiffnesses applicable to the family (notch alone).
pub fn closed_forms(spec: &HingeSpec, e: f64) -> ClosedForms {
    use closed_form as cf;
    match *spec {
        HingeSpec::CircularNotch { r, t, w, .. } => ClosedForms::new(&[
            ("paros_weisbord_full", cf::paros_weisbord_full(r, t, w, e)),
            ("paros_weisbord_simplified", cf::paros_weisbord_simplified(r, t, w, e)),
            ("wu_zhou", cf::wu_zhou(r, t, w, e)),
            (
                "smith_lobontiu_elliptical_ax_eq_ay",
                cf::smith_lobontiu_elliptical(r, r, t, w, e),
            ),
        ]),
        HingeSpec::EllipticalNotch { ax, ay, t, w, .. } => ClosedForms::new(&[(
            "smith_lobontiu_elliptical",
            cf::smith_lobontiu_elliptical(ax, ay, t, w, e),
        )]),
        HingeSpec::CornerFilleted { l, r, t, w, .. } => {
            ClosedForms::new(&[("lobontiu_corner_filleted", cf::lobontiu_corner_filleted(l, r, t, w, e))])
        }
        HingeSpec::Leaf { l, t, w, .. } => ClosedForms::new(&[("euler_bernoulli", cf::leaf(l, t, w, e))]),
        HingeSpec::SphericalNeck { l, t, r, .. } => ClosedForms::new(&[
            (
                "paros_weisbord_circular_section",
                cf::paros_weisbord_circular_section(l, t, r, e),
            ),
            (
                "paros_weisbord_circular_section_simplified",
                cf::paros_weisbord_circular_section_simplified(l, t, r, e),
            ),
        ]),
    }
}
