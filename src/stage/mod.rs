//! The monolithic 3-PRS compliant stage as one beam FE model (Ruiz et al. 2019, §5).
//!
//! Leg i runs from the revolute centre Cᵢ to the spherical centre Bᵢ (home pose of
//! [`crate::kinematics::Prs`]). Along it, from the slider up:
//!
//! * the **slider**: a rigid body guided along eᵢ. Its node sits at the lower end of the
//!   revolute notch, Cᵢ − h_r·lᵢ, with a node frame (eᵢ, mᵢ, eᵢ × mᵢ): the five DOFs other than
//!   the translation along eᵢ are fixed; that one carries the actuator force or the prescribed
//!   stroke;
//! * the **revolute notch** centred at Cᵢ, compliant axis mᵢ (the notch thins along nᵢ = lᵢ × mᵢ),
//!   as one flexibility element whose 6×6 compliance is the exact variable-section Timoshenko
//!   flexibility of the notch with Vlasov (warping-restrained) torsion ([`crate::hinge`]);
//! * the **leg**: a prismatic w × h Timoshenko beam (w along mᵢ) from the top of the notch to
//!   the bottom of the neck, in `leg_elements` elements;
//! * the **spherical neck** centred at Bᵢ, one flexibility element;
//! * the **platform**: a rigid body (rigid link from the platform centre P to the three neck
//!   tops).
//!
//! With `ideal_joints` the hinges become exact releases (revolute: every DOF tied but the
//! rotation about mᵢ; spherical: translations tied) and legs and platform are made 10⁶ times
//! stiffer: the linear FE pose must then equal the linearised rigid-body kinematics.

pub mod sizing;

use crate::fem::{self, Dof, FemError, Model};
use crate::hinge::{self, HingeSpec, Profile};
use crate::kinematics::Prs;
use crate::material::Material;
use nalgebra::{Matrix3, Matrix6, Vector3};
use thiserror::Error;

/// Errors of the stage builder and solver.
#[derive(Debug, Error)]
pub enum StageError {
    /// Non-physical stage geometry (names the stage field).
    #[error("stage field `{field}`: {message}")]
    Geometry {
        /// Field of the `stage` object, e.g. `revolute.t`.
        field: String,
        /// What is wrong and what is allowed.
        message: String,
    },
    /// The FE model failed (singular, …).
    #[error("stage FE model: {0}")]
    Fem(#[from] FemError),
}

/// A stage design: geometry, hinges, material and modelling options.
#[derive(Debug, Clone, PartialEq)]
pub struct StageDesign {
    /// Rigid-body geometry (L, b, a, γ, home height).
    pub prs: Prs,
    /// Leg section width along the revolute axis mᵢ, mm.
    pub leg_w: f64,
    /// Leg section height along nᵢ, mm.
    pub leg_h: f64,
    /// Revolute notch (its w, h are the leg's; blank length 0).
    pub revolute: HingeSpec,
    /// Spherical neck (its h is the leg's; blank length 0).
    pub spherical: HingeSpec,
    /// Material of the monolithic stage.
    pub material: Material,
    /// Replace hinges by exact joints and make legs and platform stiff.
    pub ideal_joints: bool,
    /// Beam elements per leg (≥ 1).
    pub leg_elements: usize,
}

/// Node and element numbers of one leg.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegIds {
    /// Slider node (bottom of the revolute notch).
    pub slider: usize,
    /// Top of the revolute notch.
    pub rev_top: usize,
    /// Bottom of the spherical neck.
    pub sph_bottom: usize,
    /// Top of the spherical neck (on the platform).
    pub sph_top: usize,
    /// Revolute hinge element (`usize::MAX` with ideal joints).
    pub rev_element: usize,
    /// Spherical hinge element (`usize::MAX` with ideal joints).
    pub sph_element: usize,
    /// Slider direction eᵢ.
    pub e: Vector3<f64>,
    /// Revolute axis mᵢ.
    pub m: Vector3<f64>,
    /// Leg axis lᵢ (C → B) at home.
    pub l: Vector3<f64>,
}

/// The FE model of a stage design plus what is needed to read results.
#[derive(Debug, Clone)]
pub struct StageModel {
    /// The design it was built from.
    pub design: StageDesign,
    /// The FE model (no load cases).
    pub model: Model,
    /// Platform centre node.
    pub platform: usize,
    /// Per-leg ids.
    pub legs: [LegIds; 3],
    /// Revolute notch profile (blank 0), for stresses.
    pub rev_profile: Profile,
    /// Spherical neck profile (blank 0), for stresses.
    pub sph_profile: Profile,
    /// Notch stress-concentration factors (revolute, spherical).
    pub kt: [f64; 2],
    /// Characterisation of the revolute notch alone (blank 0).
    pub rev_hinge: hinge::Stiffness,
    /// Characterisation of the spherical neck alone (blank 0).
    pub sph_hinge: hinge::Stiffness,
}

/// How one load case drives the actuators.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Drive {
    /// Actuator forces along eᵢ, N.
    Forces([f64; 3]),
    /// Prescribed strokes along eᵢ, mm.
    Strokes([f64; 3]),
}

/// Platform pose change from home: the kinematics' [`Pose`](crate::kinematics::Pose) (x, y, z in
/// mm; ψ, θ, φ in rad — in linear analyses the small-rotation vector components, in nonlinear
/// ones the angles of R = Ry(θ)·Rx(ψ)·Rz(φ)).
pub type PoseChange = crate::kinematics::Pose;

/// Result of one stage load case.
#[derive(Debug, Clone, PartialEq)]
pub struct StageCaseResult {
    /// Load-case name.
    pub name: String,
    /// Slider strokes along eᵢ, mm.
    pub strokes: [f64; 3],
    /// Actuator forces along eᵢ, N.
    pub forces: [f64; 3],
    /// Platform pose change.
    pub platform: PoseChange,
    /// Peak von Mises stress in each revolute hinge, MPa.
    pub revolute_stress: [f64; 3],
    /// Peak von Mises stress in each spherical hinge, MPa.
    pub spherical_stress: [f64; 3],
    /// Largest von Mises stress anywhere (hinges and legs), MPa.
    pub max_von_mises: f64,
    /// Raw FE result.
    pub fe: fem::CaseResult,
    /// Nonlinear solves only: whether the equilibrium path stayed stable, and if not the
    /// load factors bracketing the first loss ([`fem::NonlinearCase::critical_load_factor`]).
    pub stability: Option<(bool, Option<[f64; 2]>)>,
}

impl StageCaseResult {
    /// T = max σ_sph / max σ_rev (Ruiz et al. (2019) §5).
    pub fn t_ratio(&self) -> f64 {
        let s = self.spherical_stress.iter().cloned().fold(0.0, f64::max);
        let r = self.revolute_stress.iter().cloned().fold(0.0, f64::max);
        s / r
    }
}

fn geometry_err(field: &str, message: impl Into<String>) -> StageError {
    StageError::Geometry {
        field: field.into(),
        message: message.into(),
    }
}

fn hinge_err(prefix: &str, e: hinge::HingeError) -> StageError {
    match e {
        hinge::HingeError::InvalidGeometry { param, value, allowed } => geometry_err(
            &format!("{prefix}.{param}"),
            format!("value {value} is not allowed: {allowed}"),
        ),
        hinge::HingeError::InvalidMaterial { param, value, allowed } => geometry_err(
            &format!("material.{param}"),
            format!("value {value} is not allowed: {allowed}"),
        ),
    }
}

/// Frame rows (local x, y, z in global coordinates) as the array the FE model takes.
fn rows(x: Vector3<f64>, y: Vector3<f64>, z: Vector3<f64>) -> [[f64; 3]; 3] {
    [[x[0], x[1], x[2]], [y[0], y[1], y[2]], [z[0], z[1], z[2]]]
}

fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

/// The 6×6 compliance of a hinge region (notch + load-spreading zone) with the
/// warping-restrained torsion of [`hinge::characterise`], in hinge axes (x along the hinge,
/// y compliant axis, z across).
fn hinge_region(profile: &Profile, material: &Material, prefix: &str) -> Result<hinge::Stiffness, StageError> {
    hinge::profile_stiffness(profile, material).map_err(|e| hinge_err(prefix, e))
}

impl StageDesign {
    /// Checks the design before anything is built.
    pub fn validate(&self) -> Result<(Profile, Profile), StageError> {
        for (f, v) in [("leg.w", self.leg_w), ("leg.h", self.leg_h)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(geometry_err(
                    f,
                    format!("value {v} is not allowed: must be a positive length (mm)"),
                ));
            }
        }
        if self.leg_elements == 0 || self.leg_elements > 1000 {
            return Err(geometry_err(
                "leg_elements",
                format!("value {} is not allowed: must be in 1..=1000", self.leg_elements),
            ));
        }
        // Each hinge element spans its notch plus the stretch of leg over which load still
        // spreads out of it (Profile::spread_reach): the leg beams start beyond.
        let region = |p: Profile| Profile {
            blank: (p.spread_reach() - p.half_notch).max(0.0),
            ..p
        };
        let rp = region(self.revolute.profile().map_err(|e| hinge_err("revolute", e))?);
        let sp = region(self.spherical.profile().map_err(|e| hinge_err("spherical", e))?);
        let used = rp.half_length() + sp.half_length();
        if used >= self.prs.l {
            return Err(geometry_err(
                "L",
                format!(
                    "value {} is not allowed: the revolute notch (half-length {:.3} mm with its load-spreading zone) and the spherical neck (half-length {:.3} mm) must fit in the leg length",
                    self.prs.l, rp.half_length(), sp.half_length()
                ),
            ));
        }
        let clearance = self.prs.a_point(0).norm() - self.prs.b;
        let _ = clearance;
        Ok((rp, sp))
    }

    /// Builds the FE model (no load cases).
    pub fn build(&self) -> Result<StageModel, StageError> {
        let (rp, sp) = self.validate()?;
        let prs = &self.prs;
        let mut model = Model::new();
        let stiff = if self.ideal_joints { 1e6 } else { 1.0 };
        let leg_material = Material {
            e: self.material.e * stiff,
            ..self.material
        };
        let p = model.add_node(arr(prs.p_home()));
        let rev_h = hinge_region(&rp, &self.material, "revolute")?;
        let sph_h = hinge_region(&sp, &self.material, "spherical")?;
        let rev_c = if self.ideal_joints {
            None
        } else {
            Some(rev_h.compliance)
        };
        let sph_c = if self.ideal_joints {
            None
        } else {
            Some(sph_h.compliance)
        };
        let (hr, hs) = if self.ideal_joints {
            (0.0, 0.0)
        } else {
            (rp.half_length(), sp.half_length())
        };
        let mut legs = Vec::with_capacity(3);
        let mut platform_slaves = Vec::with_capacity(3);
        for i in 0..3 {
            let c = prs.a_point(i);
            let b = prs.b_home(i);
            let l = (b - c) / prs.l;
            let m = prs.m(i);
            let n = l.cross(&m);
            let e = prs.e(i);
            let slider = model.add_node(arr(c - hr * l));
            model.set_frame(slider, rows(e, m, e.cross(&m)));
            model.supports.push(fem::Support::dofs(
                slider,
                &[Dof::Uy, Dof::Uz, Dof::Rx, Dof::Ry, Dof::Rz],
            ));
            let rev_top = if self.ideal_joints {
                let top = model.add_node(arr(c));
                model.set_frame(top, rows(e, m, e.cross(&m)));
                // Revolute: everything tied but the rotation about mᵢ (local y of the frame).
                model.ties.push(fem::Tie {
                    a: slider,
                    b: top,
                    dofs: [true, true, true, true, false, true],
                });
                top
            } else {
                model.add_node(arr(c + hr * l))
            };
            let rev_element = match rev_c {
                Some(cmp) => model.add_element(fem::Element::Flex(fem::FlexElement {
                    nodes: [slider, rev_top],
                    compliance: cmp,
                    up: arr(n),
                })),
                None => usize::MAX,
            };
            // The leg beam from the top of the notch to the bottom of the neck.
            let start = c + hr * l;
            let end = b - hs * l;
            let mut prev = rev_top;
            for k in 1..=self.leg_elements {
                let x = start + (end - start) * (k as f64 / self.leg_elements as f64);
                let node = model.add_node(arr(x));
                // Section h along local z = nᵢ, w along local y = mᵢ (`up` = nᵢ).
                model.add_beam(fem::Beam::new(
                    prev,
                    node,
                    fem::Section::Rect {
                        w: self.leg_w,
                        h: self.leg_h,
                    },
                    leg_material,
                    arr(n),
                ));
                prev = node;
            }
            let sph_bottom = prev;
            let (sph_top, sph_element) = match sph_c {
                Some(cmp) => {
                    let top = model.add_node(arr(b + hs * l));
                    let el = model.add_element(fem::Element::Flex(fem::FlexElement {
                        nodes: [sph_bottom, top],
                        compliance: cmp,
                        up: arr(n),
                    }));
                    (top, el)
                }
                None => {
                    // Spherical: translations tied, rotations free; the platform point is an
                    // independent node joined to P by a stiff beam (see the module docs).
                    let top = model.add_node(arr(b));
                    model.ties.push(fem::Tie {
                        a: top,
                        b: sph_bottom,
                        dofs: [true, true, true, false, false, false],
                    });
                    (top, usize::MAX)
                }
            };
            platform_slaves.push(sph_top);
            legs.push(LegIds {
                slider,
                rev_top,
                sph_bottom,
                sph_top,
                rev_element,
                sph_element,
                e,
                m,
                l,
            });
        }
        if self.ideal_joints {
            let d = 2.0 * self.leg_w.max(self.leg_h);
            for &s in &platform_slaves {
                let axis = Vector3::from(model.nodes[s]) - Vector3::from(model.nodes[p]);
                let up = if axis.cross(&Vector3::z()).norm() > 1e-9 * axis.norm() {
                    Vector3::z()
                } else {
                    Vector3::x()
                };
                model.add_beam(fem::Beam::new(p, s, fem::Section::Circle { d }, leg_material, arr(up)));
            }
        } else {
            model.rigid_links.push(fem::RigidLink {
                master: p,
                slaves: platform_slaves,
            });
        }
        let legs = [legs[0], legs[1], legs[2]];
        let kt = [
            hinge::stress::stress_factor(&rp, self.material.nu),
            hinge::stress::stress_factor(&sp, self.material.nu),
        ];
        Ok(StageModel {
            design: self.clone(),
            model,
            platform: p,
            legs,
            rev_profile: rp,
            sph_profile: sp,
            kt,
            rev_hinge: rev_h,
            sph_hinge: sph_h,
        })
    }
}

/// Co-rotational elements per hinge region in the nonlinear stage solve: the region (notch +
/// load-spreading zone, ~14–25 mm for the paper's hinges) bends through up to ~2° at the paper's
/// strokes; 4 elements put Δz within 0.1 µm of 16 (tests/nonlinear.rs `stage_hinge_subdivision`).
pub const NONLINEAR_HINGE_SEGMENTS: usize = 4;

/// Peak von Mises stress along a hinge element from its end section forces (linear moment
/// variation: no loads act inside the hinge). Bending stress at the extreme fibres times the
/// notch factor K_t, plus axial stress; torsional shear τ = T·c/J (exact for thin sections,
/// conservative for thick ones); σ_vm = √(σ² + 3τ²) combining both peaks (conservative).
pub fn hinge_peak_stress(profile: &Profile, nu: f64, kt: f64, sf: &[[f64; 6]; 2], neck: bool) -> f64 {
    let half = profile.half_length();
    const N: usize = 41;
    let mut peak: f64 = 0.0;
    for k in 0..N {
        let s = k as f64 / (N - 1) as f64;
        let x = -half + 2.0 * half * s;
        let f: [f64; 6] = std::array::from_fn(|j| sf[0][j] * (1.0 - s) + sf[1][j] * s);
        let sec = profile.section(x, nu);
        let (sigma, tau) = if neck {
            let r = profile.effective_half_size(x);
            let c = r.min(0.5 * profile.h);
            let m = (f[4] * f[4] + f[5] * f[5]).sqrt();
            (f[0].abs() / sec.area + kt * m * c / sec.i_bend, f[3].abs() * c / sec.j)
        } else {
            let t = profile.effective_thickness(x);
            let w = profile.w;
            let sig =
                f[0].abs() / sec.area + kt * f[4].abs() * 0.5 * t / sec.i_bend + f[5].abs() * 0.5 * w / sec.i_bend_off;
            (sig, f[3].abs() * t.min(w) / sec.j)
        };
        peak = peak.max((sigma * sigma + 3.0 * tau * tau).sqrt());
    }
    peak
}

impl StageModel {
    /// An FE load case for a drive.
    pub fn load_case(&self, name: &str, drive: Drive) -> fem::LoadCase {
        let mut lc = fem::LoadCase::new(name);
        for (i, leg) in self.legs.iter().enumerate() {
            match drive {
                Drive::Forces(f) => {
                    let v = leg.e * f[i];
                    lc = lc.force(leg.slider, [v[0], v[1], v[2], 0.0, 0.0, 0.0]);
                }
                Drive::Strokes(s) => lc = lc.displacement(leg.slider, Dof::Ux, s[i]),
            }
        }
        lc
    }

    /// Solves load cases (grouped by drive kind so each group shares one factorisation).
    pub fn solve(&self, cases: &[(String, Drive)]) -> Result<Vec<StageCaseResult>, StageError> {
        Ok(self.analyse(cases, false)?.cases)
    }

    /// Slider stroke DOFs (local ux of each slider frame), sorted.
    fn stroke_dofs(&self) -> Vec<fem::NodeDof> {
        let mut v: Vec<fem::NodeDof> = self
            .legs
            .iter()
            .map(|l| fem::NodeDof {
                node: l.slider,
                dof: Dof::Ux,
            })
            .collect();
        v.sort();
        v
    }

    /// Solves load cases and, if asked, the 6×6 compliance of the platform centre with the
    /// sliders held. Force-driven cases share one factorisation, stroke-driven cases (and the
    /// compliance) another. Within a thread the pattern and symbolic factorisation of the last
    /// stage of the same topology are reused (sweeps and the design loop refactor numerically
    /// only).
    pub fn analyse(&self, cases: &[(String, Drive)], compliance: bool) -> Result<StageAnalysis, StageError> {
        let model = &self.model;
        let mut out: Vec<Option<StageCaseResult>> = vec![None; cases.len()];
        let lcs: Vec<fem::LoadCase> = cases.iter().map(|(n, d)| self.load_case(n, *d)).collect();
        let mut platform_compliance = None;
        for strokes in [false, true] {
            let idx: Vec<usize> = (0..cases.len())
                .filter(|&i| matches!(cases[i].1, Drive::Strokes(_)) == strokes)
                .collect();
            if idx.is_empty() && !(strokes && compliance) {
                continue;
            }
            let prescribed = if strokes { self.stroke_dofs() } else { Vec::new() };
            let sys = cached_system(model, &prescribed, usize::from(strokes))?;
            let refs: Vec<&fem::LoadCase> = idx.iter().map(|&i| &lcs[i]).collect();
            let res = sys.solve_cases(model, &refs)?;
            for (&i, r) in idx.iter().zip(res) {
                out[i] = Some(self.read(r, cases[i].1));
            }
            if strokes && compliance {
                platform_compliance = Some(sys.node_compliance(model, self.platform)?);
            }
        }
        Ok(StageAnalysis {
            cases: out.into_iter().flatten().collect(),
            compliance: platform_compliance,
        })
    }

    /// Geometrically nonlinear solve of load cases (co-rotational hinges and legs, rigid
    /// platform exact under finite rotation; see [`crate::fem::nonlinear`]) in `steps` load
    /// steps. The model is the linear one (one flexibility element per hinge, same
    /// compliances), so small strokes reproduce [`StageModel::solve`]. The platform angles are
    /// extracted from its rotation matrix R = Ry(θ)·Rx(ψ)·Rz(φ) ([`pose_angles`]); hinge
    /// stresses come from the section forces in the hinges' deformed frames.
    pub fn solve_nonlinear(&self, cases: &[(String, Drive)], steps: usize) -> Result<Vec<StageCaseResult>, StageError> {
        self.solve_nonlinear_with(cases, &self.nonlinear_options(steps))
    }

    /// Default nonlinear options for the stage: `steps` load steps, sequential solver.
    pub fn nonlinear_options(&self, steps: usize) -> fem::NonlinearOptions {
        fem::NonlinearOptions {
            steps: steps.max(1),
            track: vec![fem::NodeDof {
                node: self.platform,
                dof: Dof::Uz,
            }],
            ..Default::default()
        }
    }

    /// [`StageModel::solve_nonlinear`] with explicit solver options (each hinge region split
    /// into [`NONLINEAR_HINGE_SEGMENTS`] co-rotational elements).
    pub fn solve_nonlinear_with(
        &self,
        cases: &[(String, Drive)],
        opts: &fem::NonlinearOptions,
    ) -> Result<Vec<StageCaseResult>, StageError> {
        self.solve_nonlinear_segments(cases, opts, NONLINEAR_HINGE_SEGMENTS)
    }

    /// Nonlinear solve with each hinge split into `segments` co-rotational flexibility elements
    /// (compliances of the sub-intervals of the notch from [`hinge::segment_compliance`]; their
    /// Saint-Venant torsion compliance scaled so the chain keeps the warping-restrained torsion
    /// of the single-element hinge, so the linear response is unchanged). `segments = 1` is the
    /// linear model's single element. Hinge stresses use the end sections of the first and last
    /// segment.
    pub fn solve_nonlinear_segments(
        &self,
        cases: &[(String, Drive)],
        opts: &fem::NonlinearOptions,
        segments: usize,
    ) -> Result<Vec<StageCaseResult>, StageError> {
        let mut model = self.model.clone();
        let mut chains: Vec<(usize, usize)> = Vec::new();
        if segments > 1 {
            for leg in &self.legs {
                for (el, profile, single) in [
                    (leg.rev_element, &self.rev_profile, &self.rev_hinge),
                    (leg.sph_element, &self.sph_profile, &self.sph_hinge),
                ] {
                    if el != usize::MAX {
                        let last = self.split_hinge(&mut model, el, profile, single, segments)?;
                        chains.push((el, last));
                    }
                }
            }
        }
        model.load_cases = cases.iter().map(|(n, d)| self.load_case(n, *d)).collect();
        let res = fem::solve_nonlinear(&model, opts)?;
        Ok(res
            .load_cases
            .into_iter()
            .zip(cases)
            .map(|(nl, (_, d))| {
                let r = nl.rotations[self.platform];
                let rm = Matrix3::from_fn(|i, j| r[i][j]);
                let (psi, theta, phi) = pose_angles(&rm);
                let mut fe = nl.fe;
                for &(first, last) in &chains {
                    let end = fe.elements[last].section_forces[1];
                    fe.elements[first].section_forces[1] = end;
                }
                let mut out = self.read(fe, *d);
                out.stability = Some((nl.stable, nl.critical_load_factor));
                out.platform.psi = psi;
                out.platform.theta = theta;
                out.platform.phi = phi;
                out
            })
            .collect())
    }

    /// Replaces hinge element `el` by a chain of `n` flexibility elements; returns the index of
    /// the last one (the first keeps index `el`).
    fn split_hinge(
        &self,
        model: &mut Model,
        el: usize,
        profile: &Profile,
        single: &hinge::Stiffness,
        n: usize,
    ) -> Result<usize, StageError> {
        let Some(fem::Element::Flex(f)) = model.elements.get(el).cloned() else {
            return Err(StageError::Fem(FemError::BadInput(format!(
                "element {el} is not a hinge flexibility element"
            ))));
        };
        let (a, b) = (
            Vector3::from(model.nodes[f.nodes[0]]),
            Vector3::from(model.nodes[f.nodes[1]]),
        );
        let half = profile.half_length();
        let material = &self.design.material;
        let xs: Vec<f64> = (0..=n).map(|k| -half + 2.0 * half * k as f64 / n as f64).collect();
        let cs: Vec<Matrix6<f64>> = xs
            .windows(2)
            .map(|w| hinge::segment_compliance(profile, material, w[0], w[1]))
            .collect();
        let sv: f64 = cs.iter().map(|c| c[(3, 3)]).sum();
        let scale = single.compliance[3][3] / sv;
        let mut prev = f.nodes[0];
        let mut last = el;
        for (k, c) in cs.iter().enumerate() {
            let next = if k + 1 == n {
                f.nodes[1]
            } else {
                let x = a + (b - a) * ((k + 1) as f64 / n as f64);
                model.add_node([x[0], x[1], x[2]])
            };
            let mut cm = [[0.0; 6]; 6];
            for (i, row) in cm.iter_mut().enumerate() {
                for (j, v) in row.iter_mut().enumerate() {
                    *v = c[(i, j)] * if i == 3 && j == 3 { scale } else { 1.0 };
                }
            }
            let e = fem::Element::Flex(fem::FlexElement {
                nodes: [prev, next],
                compliance: cm,
                up: f.up,
            });
            if k == 0 {
                model.elements[el] = e;
            } else {
                last = model.add_element(e);
            }
            prev = next;
        }
        Ok(last)
    }

    /// Reads stage quantities from an FE load-case result driven by `drive`.
    pub fn read(&self, fe: fem::CaseResult, drive: Drive) -> StageCaseResult {
        let nu = self.design.material.nu;
        let mut strokes = [0.0; 3];
        let mut forces = [0.0; 3];
        let mut rev = [0.0; 3];
        let mut sph = [0.0; 3];
        for (i, leg) in self.legs.iter().enumerate() {
            let u = &fe.displacements[leg.slider];
            strokes[i] = leg.e.dot(&Vector3::new(u[0], u[1], u[2]));
            // Actuator force along eᵢ: the applied force, or with a prescribed stroke the
            // reaction of the stroke DOF (the guide's other reactions are normal to eᵢ).
            forces[i] = match drive {
                Drive::Forces(f) => f[i],
                Drive::Strokes(_) => fe
                    .reactions
                    .iter()
                    .find(|(n, _)| *n == leg.slider)
                    .map_or(0.0, |(_, r)| leg.e.dot(&Vector3::new(r[0], r[1], r[2]))),
            };
            if leg.rev_element != usize::MAX {
                let sf = &fe.elements[leg.rev_element].section_forces;
                rev[i] = hinge_peak_stress(&self.rev_profile, nu, self.kt[0], sf, false);
            }
            if leg.sph_element != usize::MAX {
                let sf = &fe.elements[leg.sph_element].section_forces;
                sph[i] = hinge_peak_stress(&self.sph_profile, nu, self.kt[1], sf, true);
            }
        }
        let up = fe.displacements[self.platform];
        let beams = fe.max_von_mises.unwrap_or(0.0);
        let max_vm = rev.iter().chain(sph.iter()).cloned().fold(beams, f64::max);
        StageCaseResult {
            name: fe.name.clone(),
            strokes,
            forces,
            platform: PoseChange {
                x: up[0],
                y: up[1],
                z: up[2],
                psi: up[3],
                theta: up[4],
                phi: up[5],
            },
            revolute_stress: rev,
            spherical_stress: sph,
            max_von_mises: max_vm,
            fe,
            stability: None,
        }
    }

    /// 6×6 compliance of the platform centre with the sliders held (mm, N, rad).
    pub fn platform_compliance(&self) -> Result<Matrix6<f64>, StageError> {
        let a = self.analyse(&[], true)?;
        a.compliance
            .ok_or_else(|| StageError::Fem(FemError::Solver("no compliance computed".into())))
    }
}

/// Results of [`StageModel::analyse`].
#[derive(Debug, Clone)]
pub struct StageAnalysis {
    /// Load-case results in input order.
    pub cases: Vec<StageCaseResult>,
    /// Platform-centre compliance with the sliders held, if asked.
    pub compliance: Option<Matrix6<f64>>,
}

thread_local! {
    /// The last factorised stage system of this thread, per drive kind (forces, strokes).
    static LAST: std::cell::RefCell<[Option<fem::System>; 2]> = const { std::cell::RefCell::new([None, None]) };
}

/// A factorised system for `model`, reusing the pattern and symbolic factorisation of the last
/// system of the same kind on this thread when the topology matches.
fn cached_system(model: &Model, prescribed: &[fem::NodeDof], kind: usize) -> Result<fem::System, StageError> {
    let par = fem::solve::Parallelism::Sequential;
    let reused = LAST.with(|c| {
        c.borrow()[kind]
            .as_ref()
            .filter(|s| s.prescribed() == prescribed)
            .and_then(|s| fem::System::with_topology_of(s, model, par).ok())
    });
    let sys = match reused {
        Some(s) => s,
        None => fem::System::new(model, prescribed, par)?,
    };
    LAST.with(|c| c.borrow_mut()[kind] = Some(sys.clone()));
    Ok(sys)
}

/// Total actuator force per mm of stroke for a pure-z motion, N/mm: the sum of the actuator
/// forces when every stroke follows the linearised IKP of a unit z lift.
pub fn stiffness_z(stage: &StageModel) -> Result<(f64, StageCaseResult), StageError> {
    let j = stage
        .design
        .prs
        .actuation_jacobian(0.0, 0.0, 0.0)
        .map_err(|e| geometry_err("L", e.to_string()))?;
    let s = [j[(0, 0)], j[(1, 0)], j[(2, 0)]];
    let mut r = stage.solve(&[("unit_z".to_string(), Drive::Strokes(s))])?;
    let r = r.remove(0);
    let total: f64 = r.forces.iter().sum();
    Ok((total / (s.iter().sum::<f64>() / 3.0), r))
}

/// Angles (ψ, θ, φ) of R = Ry(θ)·Rx(ψ)·Rz(φ) (the platform orientation of
/// [`crate::kinematics::prs::orientation`]), rad: row 2 of R is (cψ sφ, cψ cφ, −sψ) and its
/// column 3 is (sθ cψ, −sψ, cθ cψ).
pub fn pose_angles(r: &Matrix3<f64>) -> (f64, f64, f64) {
    let psi = (-r[(1, 2)]).atan2((r[(1, 0)].powi(2) + r[(1, 1)].powi(2)).sqrt());
    let phi = r[(1, 0)].atan2(r[(1, 1)]);
    let theta = r[(0, 2)].atan2(r[(2, 2)]);
    (psi, theta, phi)
}

/// Frame helper re-exported for tests.
pub fn frame_of(leg: &LegIds) -> Matrix3<f64> {
    Matrix3::from_rows(&[leg.e.transpose(), leg.m.transpose(), leg.e.cross(&leg.m).transpose()])
}
