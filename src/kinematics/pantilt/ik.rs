//! Construction and closed-form inverse kinematics of the pan-tilt PRBM (limb by limb).

use super::*;

impl PanTilt {
    /// Validates a geometry. δ and θ₀ in (0°, 180°), a home pose must exist
    /// (|cos θ₀| < sin δ), azimuths pairwise distinct, limb indices in 0..3, the actuated limbs
    /// distinct, and the actuation Jacobian regular at home.
    pub fn new(geometry: PanTiltGeometry) -> Result<Self, PanTiltError> {
        let g = &geometry;
        let finite = g.theta0.is_finite() && g.delta.is_finite();
        if !finite || g.theta0 <= 0.0 || g.theta0 >= PI {
            return Err(PanTiltError::Geometry(format!(
                "θ₀ = {}° must lie in (0°, 180°)",
                g.theta0.to_degrees()
            )));
        }
        if g.delta <= 0.0 || g.delta >= PI {
            return Err(PanTiltError::Geometry(format!(
                "δ = {}° must lie in (0°, 180°)",
                g.delta.to_degrees()
            )));
        }
        let s = g.theta0.cos() / g.delta.sin();
        if s.abs() >= 1.0 - 1e-9 {
            return Err(PanTiltError::Geometry(format!(
                "no home pose: cos θ₀ / sin δ = {s} (θ₀ = {}°, δ = {}°) must lie strictly inside (−1, 1)",
                g.theta0.to_degrees(),
                g.delta.to_degrees()
            )));
        }
        for (i, e) in g.azimuths.iter().enumerate() {
            if !e.is_finite() {
                return Err(PanTiltError::Geometry(format!(
                    "azimuth of limb {} is not finite",
                    i + 1
                )));
            }
        }
        for i in 0..3 {
            for j in i + 1..3 {
                if wrap(g.azimuths[i] - g.azimuths[j]).abs() < 1e-6 {
                    return Err(PanTiltError::Geometry(format!(
                        "limbs {} and {} share the azimuth {}°",
                        i + 1,
                        j + 1,
                        g.azimuths[i].to_degrees()
                    )));
                }
            }
        }
        if g.rr_limb > 2 {
            return Err(PanTiltError::Geometry(format!(
                "RR limb {} must be 1, 2 or 3",
                g.rr_limb + 1
            )));
        }
        if g.actuated.iter().any(|&a| a > 2) || g.actuated[0] == g.actuated[1] {
            return Err(PanTiltError::Geometry(format!(
                "actuated limbs {:?} must be two distinct limbs of 1, 2, 3",
                g.actuated.map(|a| a + 1)
            )));
        }
        let mut rrr = [0usize; 2];
        let mut k = 0;
        for j in 0..3 {
            if j != g.rr_limb {
                rrr[k] = j;
                k += 1;
            }
        }
        let mut model = Self {
            geometry,
            beta: s.asin(),
            rrr,
            home_mid: [0.0; 3],
            home_top: [0.0; 2],
        };
        let home = Pointing { gamma: 0.0, phi: 0.0 };
        let (mid, top) = model.raw_angles(&model.limbs(&home)?, &home.axis());
        model.home_mid = mid;
        model.home_top = top;
        model.actuation_jacobian(&home)?;
        Ok(model)
    }

    /// The geometry.
    pub fn geometry(&self) -> &PanTiltGeometry {
        &self.geometry
    }

    /// Home elevation β of the middle axes, rad.
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// The two RRR limbs (0-based, ascending); their top joints are J7 and J8.
    pub fn rrr_limbs(&self) -> [usize; 2] {
        self.rrr
    }

    /// Closed-form IK of the three limbs (Yu et al. Eqs. 1–11 generalised to any δ): for each
    /// limb, `A cos α + B sin α = C` with `A = sin δ (h·r₇)`, `B = sin δ r₇z`,
    /// `C = cos θ₀ − cos δ (u·r₇)`, solved as `α = asin(C/R) − atan2(A, B)`, R = √(A² + B²):
    /// the branch through the home pose (α = β at γ = 0), continuous until the two branches meet.
    pub(super) fn limbs(&self, pose: &Pointing) -> Result<[Limb; 3], PanTiltError> {
        let r7 = pose.axis();
        let (sd, cd) = self.geometry.delta.sin_cos();
        let ct0 = self.geometry.theta0.cos();
        let z = Vector3::z();
        let mut out = [Limb {
            u: z,
            m: z,
            m_alpha: z,
            alpha: 0.0,
            dalpha: z,
        }; 3];
        for (j, limb) in out.iter_mut().enumerate() {
            let (se, ce) = self.geometry.azimuths[j].sin_cos();
            let u = Vector3::new(se, -ce, 0.0);
            let h = Vector3::new(ce, se, 0.0);
            let a = sd * h.dot(&r7);
            let b = sd * r7.z;
            let c = ct0 - cd * u.dot(&r7);
            let r = a.hypot(b);
            let ratio = c / r;
            if !ratio.is_finite() || ratio.abs() > 1.0 {
                return Err(PanTiltError::Unreachable {
                    limb: j + 1,
                    gamma_deg: pose.gamma.to_degrees(),
                    phi_deg: pose.phi.to_degrees(),
                    ratio,
                });
            }
            let alpha = wrap(ratio.asin() - a.atan2(b));
            let (sa, ca) = alpha.sin_cos();
            let m = cd * u + sd * (ca * h + sa * z);
            let m_alpha = sd * (-sa * h + ca * z);
            let den = r7.dot(&m_alpha);
            if den.abs() < 1e-12 {
                return Err(PanTiltError::LimbSingular {
                    limb: j + 1,
                    gamma_deg: pose.gamma.to_degrees(),
                    phi_deg: pose.phi.to_degrees(),
                    den,
                });
            }
            *limb = Limb {
                u,
                m,
                m_alpha,
                alpha,
                // m·r₇ = cos θ₀ ⇒ (r₇·m_α) dα + m·dr₇ = 0 (Yu et al. Eq. 15).
                dalpha: -m / den,
            };
        }
        Ok(out)
    }

    /// Raw (not home-referenced) middle and top joint angles.
    fn raw_angles(&self, limbs: &[Limb; 3], r7: &Vector3<f64>) -> ([f64; 3], [f64; 2]) {
        let cd = self.geometry.delta.cos();
        let ct0 = self.geometry.theta0.cos();
        let mut mid = [0.0; 3];
        for (j, l) in limbs.iter().enumerate() {
            let (y, x) = angle_parts(&l.m, &l.u, r7, cd * ct0);
            mid[j] = y.atan2(x);
        }
        let p = &limbs[self.geometry.rr_limb].m;
        let mut top = [0.0; 2];
        for (k, &j) in self.rrr.iter().enumerate() {
            let (y, x) = angle_parts(r7, &limbs[j].m, p, ct0 * ct0);
            top[k] = y.atan2(x);
        }
        (mid, top)
    }

    /// Actuated joint angles (θ₁, θ₂ of the actuated limbs), rad, by the closed-form IK.
    pub fn inverse_kinematics(&self, pose: &Pointing) -> Result<[f64; 2], PanTiltError> {
        let limbs = self.limbs(pose)?;
        let [a, b] = self.geometry.actuated;
        Ok([wrap(limbs[a].alpha - self.beta), wrap(limbs[b].alpha - self.beta)])
    }

    /// All eight joint rotations from home and their gradients.
    ///
    /// Middle joint j (J4–J6): rotation of the outer body (upper link, or the platform for the
    /// RR limb) relative to the lower link about mⱼ, i.e. the change of the signed angle from uⱼ to
    /// r₇ about mⱼ. Top joint (J7, J8): rotation of the platform relative to the upper link about
    /// r₇, the change of the signed angle from mⱼ to the platform-fixed m_RR about r₇.
    pub fn joint_state(&self, pose: &Pointing) -> Result<JointState, PanTiltError> {
        let limbs = self.limbs(pose)?;
        let r7 = pose.axis();
        let cd = self.geometry.delta.cos();
        let ct0 = self.geometry.theta0.cos();
        // Tangents of r₇: s = (r₇ₓ, r₇ᵧ) and x = (γ, φ).
        let ts = regular_tangents(&r7);
        let tx = pose.axis_derivatives();
        let mut q = [0.0; JOINTS];
        let mut grad_s = [Vector2::zeros(); JOINTS];
        let mut grad_x = [Vector2::zeros(); JOINTS];
        // d(angle) along a tangent dr of r₇, per joint.
        let dq = |dr: &Vector3<f64>| -> [f64; JOINTS] {
            let mut d = [0.0; JOINTS];
            let dm = limbs.map(|l| l.m_alpha * l.dalpha.dot(dr));
            for (j, l) in limbs.iter().enumerate() {
                d[j] = l.dalpha.dot(dr);
                let (y, x) = angle_parts(&l.m, &l.u, &r7, cd * ct0);
                let dy = dm[j].dot(&l.u.cross(&r7)) + l.m.dot(&l.u.cross(dr));
                let dx = l.u.dot(dr);
                d[3 + j] = datan2(y, x, dy, dx);
            }
            let rr = self.geometry.rr_limb;
            let p = &limbs[rr].m;
            for (k, &j) in self.rrr.iter().enumerate() {
                let mj = &limbs[j].m;
                let (y, x) = angle_parts(&r7, mj, p, ct0 * ct0);
                let dy = dr.dot(&mj.cross(p)) + r7.dot(&dm[j].cross(p)) + r7.dot(&mj.cross(&dm[rr]));
                let dx = dm[j].dot(p) + mj.dot(&dm[rr]);
                d[6 + k] = datan2(y, x, dy, dx);
            }
            d
        };
        let ds = [dq(&ts[0]), dq(&ts[1])];
        let dx = [dq(&tx[0]), dq(&tx[1])];
        let (mid, top) = self.raw_angles(&limbs, &r7);
        for j in 0..3 {
            q[j] = wrap(limbs[j].alpha - self.beta);
            q[3 + j] = wrap(mid[j] - self.home_mid[j]);
        }
        for k in 0..2 {
            q[6 + k] = wrap(top[k] - self.home_top[k]);
        }
        for i in 0..JOINTS {
            grad_s[i] = Vector2::new(ds[0][i], ds[1][i]);
            grad_x[i] = Vector2::new(dx[0][i], dx[1][i]);
        }
        Ok(JointState { q, grad_s, grad_x })
    }

    /// The paper's 2×2 inverse Jacobian J with θ̇_a = J·[γ̇, φ̇] (Yu et al. Eqs. 15–17:
    /// row j = [Qⱼ/Pⱼ, Rⱼ/Pⱼ]). Its second column is ∝ sin γ: at γ = 0 (the home pose) it is
    /// singular because φ is undefined there, which is a singularity of the (γ, φ) coordinates,
    /// not of the mechanism (see [`PanTilt::actuation_jacobian`]). Returns
    /// [`PanTiltError::PoleSingular`] when |sin γ| < 1e-12.
    pub fn inverse_jacobian(&self, pose: &Pointing) -> Result<Matrix2<f64>, PanTiltError> {
        if pose.gamma.sin().abs() < 1e-12 {
            return Err(PanTiltError::PoleSingular {
                gamma_deg: pose.gamma.to_degrees(),
            });
        }
        let limbs = self.limbs(pose)?;
        let tx = pose.axis_derivatives();
        let [a, b] = self.geometry.actuated;
        Ok(Matrix2::new(
            limbs[a].dalpha.dot(&tx[0]),
            limbs[a].dalpha.dot(&tx[1]),
            limbs[b].dalpha.dot(&tx[0]),
            limbs[b].dalpha.dot(&tx[1]),
        ))
    }
}
