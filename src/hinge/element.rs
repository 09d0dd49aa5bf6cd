//! A hinge as one element of a mechanism model: the flexibility of a hinge region between two
//! nodes and the peak-stress model read from the element's end forces.
//!
//! A mechanism model (the 3-PRS stage, a mesh case) joins two nodes by a hinge. The element
//! spans the notch plus a stretch of the blank section on each side; its 6×6 compliance is the
//! exact variable-section Timoshenko flexibility of that whole region with the solid-calibrated
//! three-dimensional factors and warping-restrained torsion of [`super::characterise`] (load
//! spreading out of the notch into the blank is part of the region, so the region is *not* the
//! notch compliance in series with prismatic blank beams: those would be too stiff where load
//! still spreads, and Vlasov torsion depends on where warping is restrained). Compliances are in
//! hinge axes: x along the hinge, y the compliant axis, z across; rows/columns
//! (ux, uy, uz, rx, ry, rz), units mm/N, 1/N, rad/(N·mm).
//!
//! * [`hinge_element`]: the element between two nodes a distance L apart (blank L/2 − half
//!   notch on each side). With L = notch length + 2·`blank_length` it reproduces the compliance of
//!   the `hinge` analysis of the same spec.
//! * [`spreading_region`] + [`flex_region`]: the shortest region that still holds the whole
//!   load-spreading zone, as the stage uses for its revolute and spherical joints.
//! * [`HingeRegion::peak_stress`]: peak von Mises stress from the end section forces.
//! * [`flex_chain`]: a hinge in its blank as a chain of flexibility segments (finite rotations).

use super::profile::{Contour, Profile};
use super::{error::geom, profile_stiffness, stress, HingeError, HingeSpec, Stiffness};
use crate::material::Material;

/// One hinge region between two nodes: its profile, flexibility and stress model.
#[derive(Debug, Clone, PartialEq)]
pub struct HingeRegion {
    /// The profile of the region: the notch and `profile.blank` of blank on each side, mm.
    pub profile: Profile,
    /// Stiffness, 6×6 compliance (Vlasov torsion for rectangular notches) and stress per
    /// moment of the region between its two end faces.
    pub stiffness: Stiffness,
    /// Factor on the nominal beam stress giving the peak von Mises stress
    /// ([`stress::stress_factor`]).
    pub kt: f64,
    /// Poisson's ratio of the material (for the shear coefficients of the sections).
    pub nu: f64,
}

impl HingeRegion {
    /// 6×6 compliance of the region, one end face clamped and the load at the centre of the
    /// other (hinge axes, see the module docs).
    pub fn compliance(&self) -> [[f64; 6]; 6] {
        self.stiffness.compliance
    }

    /// Half of the node distance the region spans, mm.
    pub fn half_length(&self) -> f64 {
        self.profile.half_length()
    }

    /// Geometric volume of the region (notch and blanks), mm³ ([`profile_volume`]).
    pub fn volume(&self) -> f64 {
        profile_volume(&self.profile)
    }

    /// Whether the region is a turned neck (circular waist) rather than a flat notch.
    pub fn is_neck(&self) -> bool {
        matches!(self.profile.contour, Contour::SphericalNeck { .. })
    }

    /// Peak von Mises stress along the region, MPa, from its end section forces `sf[end]` =
    /// (N, V_y, V_z, T, M_y, M_z) in hinge axes, N and N·mm ([`hinge_peak_stress`]).
    pub fn peak_stress(&self, sf: &[[f64; 6]; 2]) -> f64 {
        hinge_peak_stress(&self.profile, self.nu, self.kt, sf, self.is_neck())
    }

    /// The region's [`PeakStressTable`]: [`Self::peak_stress`] for many load cases.
    pub fn peak_stress_table(&self) -> PeakStressTable {
        PeakStressTable::new(&self.profile, self.nu, self.kt, self.is_neck())
    }
}

/// The flexibility and stress model of a validated profile as it stands (its own blank).
///
/// Errors: the material constants E, ν or the allowable stress are outside their physical
/// range ([`HingeError::InvalidMaterial`]).
pub fn flex_region(profile: &Profile, material: &Material) -> Result<HingeRegion, HingeError> {
    Ok(HingeRegion {
        profile: *profile,
        stiffness: profile_stiffness(profile, material)?,
        kt: stress::stress_factor(profile, material.nu),
        nu: material.nu,
    })
}

/// The profile extended by blank over the stretch in which load still spreads out of the notch
/// ([`Profile::spread_reach`]; no blank if the contour needs no spreading): the shortest
/// region whose end faces carry the full blank section.
pub fn spreading_region(profile: Profile) -> Profile {
    Profile {
        blank: (profile.spread_reach() - profile.half_notch).max(0.0),
        ..profile
    }
}

/// The hinge `spec` (its own `blank_length` ignored) as one element between two nodes a
/// distance `length` apart, mm: the notch centred between them and the hinge's blank section
/// (w × h, or the neck's h × h) over the rest, `length`/2 − half notch on each side.
///
/// With `length` = notch length + 2·`blank_length` the compliance is that of
/// [`super::characterise`] for `spec` (hinge in its blank), and [`HingeRegion::peak_stress`] uses
/// the same stress model as the `hinge` analysis.
///
/// Errors: invalid geometry or material ([`HingeError`]); `length` not finite or shorter than
/// the notch (parameter `length`).
pub fn hinge_element(spec: &HingeSpec, material: &Material, length: f64) -> Result<HingeRegion, HingeError> {
    let notch = spec.profile_with_blank(Some(0.0))?;
    let notch_length = 2.0 * notch.half_notch;
    if !(length.is_finite() && length >= notch_length) {
        return Err(geom(
            "length",
            length,
            format!("the node distance must be at least the notch length {notch_length} mm"),
        ));
    }
    let blank = (0.5 * length - notch.half_notch).max(0.0);
    flex_region(&spec.profile_with_blank(Some(blank))?, material)
}

/// A hinge in its blank as a chain of flexibility segments along x, for finite-rotation
/// models (a co-rotational element per segment): the stations x (from −half-length: the blank
/// on each side as one segment when there is blank, the notch in `n` equal segments) and the
/// 6×6 compliance of each sub-interval between consecutive stations
/// ([`super::segment_compliance`], hinge axes, see the module docs).
pub fn flex_chain(profile: &Profile, material: &Material, n: usize) -> (Vec<f64>, Vec<[[f64; 6]; 6]>) {
    let (half, hn) = (profile.half_length(), profile.half_notch);
    let mut xs = vec![-half];
    if profile.blank > 0.0 {
        xs.push(-hn);
    }
    for k in 1..=n {
        xs.push(-hn + 2.0 * hn * k as f64 / n as f64);
    }
    if profile.blank > 0.0 {
        xs.push(half);
    }
    let compliances = xs
        .windows(2)
        .map(|w| {
            let c = super::segment_compliance(profile, material, w[0], w[1]);
            std::array::from_fn(|a| std::array::from_fn(|b| c[(a, b)]))
        })
        .collect();
    (xs, compliances)
}

/// Peak von Mises stress along a hinge element from its end section forces (linear moment
/// variation: no loads act inside the hinge), MPa. Bending stress at the extreme fibres times
/// the notch factor `kt`, plus axial stress; torsional shear τ = T·c/J (exact for thin
/// sections, conservative for thick ones); σ_vm = √(σ² + 3τ²) combining both peaks
/// (conservative). `neck`: circular waist (bending about y and z combined).
pub fn hinge_peak_stress(profile: &Profile, nu: f64, kt: f64, sf: &[[f64; 6]; 2], neck: bool) -> f64 {
    PeakStressTable::new(profile, nu, kt, neck).peak(sf)
}

/// Stations along a hinge at which [`hinge_peak_stress`] evaluates the stress.
const PEAK_STATIONS: usize = 41;

/// The section quantities [`hinge_peak_stress`] reads at its stations, evaluated once per
/// hinge so that the peak stress of many load cases costs a few flops each (same expressions,
/// same result to the last bit).
#[derive(Debug, Clone, PartialEq)]
pub struct PeakStressTable {
    kt: f64,
    /// Flat notch: the constant width w; `None` for a turned neck.
    width: Option<f64>,
    /// Per station: area, I_bend, I_bend_off, J, and the fibre distance (neck: c; flat: t).
    stations: [[f64; 5]; PEAK_STATIONS],
}

impl PeakStressTable {
    /// The table of `profile` for Poisson's ratio `nu`, notch factor `kt`; `neck`: circular waist.
    pub fn new(profile: &Profile, nu: f64, kt: f64, neck: bool) -> PeakStressTable {
        let half = profile.half_length();
        let stations = std::array::from_fn(|k| {
            let s = k as f64 / (PEAK_STATIONS - 1) as f64;
            let x = -half + 2.0 * half * s;
            let sec = profile.section(x, nu);
            let len = if neck {
                profile.effective_half_size(x).min(0.5 * profile.h)
            } else {
                profile.effective_thickness(x)
            };
            [sec.area, sec.i_bend, sec.i_bend_off, sec.j, len]
        });
        PeakStressTable {
            kt,
            width: (!neck).then_some(profile.w),
            stations,
        }
    }

    /// Peak von Mises stress from the end section forces (see [`hinge_peak_stress`]), MPa.
    pub fn peak(&self, sf: &[[f64; 6]; 2]) -> f64 {
        let kt = self.kt;
        let mut peak: f64 = 0.0;
        for (k, &[area, i_bend, i_bend_off, j, len]) in self.stations.iter().enumerate() {
            let s = k as f64 / (PEAK_STATIONS - 1) as f64;
            let f: [f64; 6] = std::array::from_fn(|j| sf[0][j] * (1.0 - s) + sf[1][j] * s);
            let (sigma, tau) = match self.width {
                None => {
                    let c = len;
                    let m = (f[4] * f[4] + f[5] * f[5]).sqrt();
                    (f[0].abs() / area + kt * m * c / i_bend, f[3].abs() * c / j)
                }
                Some(w) => {
                    let t = len;
                    let sig =
                        f[0].abs() / area + kt * f[4].abs() * 0.5 * t / i_bend + f[5].abs() * 0.5 * w / i_bend_off;
                    (sig, f[3].abs() * t.min(w) / j)
                }
            };
            peak = peak.max((sigma * sigma + 3.0 * tau * tau).sqrt());
        }
        peak
    }
}

/// Geometric volume of a hinge profile (notch and blanks), mm³: Simpson's rule on 2000
/// intervals over the notch, exact over the prismatic blanks.
pub fn profile_volume(p: &Profile) -> f64 {
    let area = |x: f64| match p.contour {
        Contour::SphericalNeck { .. } => {
            if x.abs() >= p.half_notch {
                p.h * p.h
            } else {
                super::section::clipped_disk(p.thickness(x) / 2.0, p.h, 0.3).area
            }
        }
        _ => p.w * p.thickness(x),
    };
    let n = 2000;
    let (x0, dx) = (-p.half_notch, 2.0 * p.half_notch / n as f64);
    let mut s = 0.0;
    for i in 0..=n {
        let wgt = if i == 0 || i == n { 1.0 } else { [2.0, 4.0][i % 2] };
        // The notch's end values from inside (a leaf's thickness jumps to h at its ends).
        s += wgt * area((x0 + i as f64 * dx) * (1.0 - 1e-12));
    }
    s * dx / 3.0 + 2.0 * p.blank * area(p.half_length())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hinge::characterise;

    /// One hinge per family, in a blank (the Ruiz et al. (2019) revolute notch R 5, t 1 in a
    /// 10 × 8 blank and comparable geometry for the others).
    fn families() -> [HingeSpec; 5] {
        let (w, h, blank_length) = (10.0, 8.0, 4.0);
        [
            HingeSpec::CircularNotch {
                r: 5.0,
                t: 1.0,
                w,
                h,
                blank_length,
            },
            HingeSpec::EllipticalNotch {
                ax: 6.0,
                ay: 3.0,
                t: 1.2,
                w,
                h,
                blank_length,
            },
            HingeSpec::CornerFilleted {
                l: 8.0,
                r: 2.0,
                t: 1.0,
                w,
                h,
                blank_length,
            },
            HingeSpec::Leaf {
                l: 6.0,
                t: 0.8,
                w,
                h,
                blank_length,
            },
            HingeSpec::SphericalNeck {
                l: 2.0,
                t: 2.0,
                r: 2.0,
                h,
                blank_length,
            },
        ]
    }

    fn max_rel_diff(a: &[[f64; 6]; 6], b: &[[f64; 6]; 6]) -> f64 {
        let scale = a.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
        a.iter()
            .flatten()
            .zip(b.iter().flatten())
            .fold(0.0, |m, (x, y)| m.max((x - y).abs() / scale))
    }

    /// The element spanning notch + 2·blank_length is the `hinge` analysis's hinge in its
    /// blank, bar the rigid end faces: with them ([`Profile::with_rigid_end_faces`]) the region
    /// has the `hinge` analysis's 6×6 compliance exactly; the element, whose ends are nodes in
    /// continuous material, has the same compliance to 1e-12 of its largest entry (only the node
    /// distance's rounding separates them) except the torsion entry, which the end faces can
    /// only stiffen; the same stress factor, for all five families.
    #[test]
    fn element_reproduces_characterise_for_every_family() {
        let m = Material::AL7075;
        for spec in families() {
            let reference = characterise(&spec, &m).unwrap();
            let p = spec.profile().unwrap();
            let r = flex_region(&p.with_rigid_end_faces(), &m).unwrap();
            assert_eq!(r.compliance(), reference.hinge.compliance, "{spec:?}");
            let e = hinge_element(&spec, &m, 2.0 * p.half_length()).unwrap();
            assert_eq!(e.profile.end_faces, crate::hinge::EndFaces::Continuous);
            let mut face_free = reference.hinge.compliance;
            face_free[3][3] = e.compliance()[3][3];
            let d = max_rel_diff(&face_free, &e.compliance());
            assert!(d < 1e-12, "{spec:?}: compliance differs by {d:e}");
            assert!(e.compliance()[3][3] >= reference.hinge.compliance[3][3], "{spec:?}");
            assert_eq!(e.kt, reference.stress_concentration, "{spec:?}");
        }
    }

    /// A node distance shorter than the notch (or not finite) is refused, naming `length`.
    #[test]
    fn element_shorter_than_the_notch_is_refused() {
        let spec = families()[0];
        // The circular notch R 5 is capped by the 8 mm blank: notch length 2·√(R² − (R − 3.5)²).
        let notch_length = 2.0 * spec.profile_with_blank(Some(0.0)).unwrap().half_notch;
        assert!((notch_length - 2.0 * (25.0f64 - 1.5 * 1.5).sqrt()).abs() < 1e-12);
        for bad in [0.99 * notch_length, f64::NAN, f64::INFINITY] {
            match hinge_element(&spec, &Material::AL7075, bad) {
                Err(HingeError::InvalidGeometry { param: "length", .. }) => {}
                other => panic!("length {bad}: {other:?}"),
            }
        }
        // Exactly the notch is allowed: no blank.
        let e = hinge_element(&spec, &Material::AL7075, notch_length).unwrap();
        assert_eq!(e.profile.blank, 0.0);
    }

    /// Peak stress under a pure compliant-axis moment M is the characterisation's stress per
    /// moment times M (beam stress at the waist, 6M/(w t²) for the flat notches, 32M/(π t³) for
    /// the neck, times the notch factor; the waist is the most stressed section).
    #[test]
    fn peak_stress_of_pure_moment_is_stress_per_moment() {
        let m = Material::AL7075;
        for spec in families() {
            let e = hinge_element(&spec, &m, 2.0 * spec.profile().unwrap().half_length()).unwrap();
            let moment = 1000.0;
            let sf = [[0.0, 0.0, 0.0, 0.0, moment, 0.0]; 2];
            let got = e.peak_stress(&sf);
            let want = e.stiffness.stress_per_moment * moment;
            assert!((got - want).abs() <= 1e-12 * want, "{spec:?}: {got} vs {want}");
        }
    }

    /// The stage's region reaches just as far as load spreads: a circular notch's contour
    /// steepens past slope 1/2 before the blank, so its region holds some blank.
    #[test]
    fn spreading_region_covers_the_spreading_zone() {
        let spec = families()[0];
        let p = spec.profile_with_blank(Some(0.0)).unwrap();
        let r = spreading_region(p);
        assert_eq!(r.half_length(), p.spread_reach().max(p.half_notch));
        assert!(r.blank > 0.0);
    }
}
