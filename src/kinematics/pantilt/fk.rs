//! Actuation Jacobian, forward kinematics (Newton on the closed-form IK) and path torques of
//! the pan-tilt PRBM.

use super::*;

impl PanTilt {
    /// The actuation Jacobian ∂θ_a/∂s in the regular coordinates s = (r₇ₓ, r₇ᵧ), regular at
    /// γ = 0; an error if it is singular (the actuators lose control of the platform).
    pub fn actuation_jacobian(&self, pose: &Pointing) -> Result<Matrix2<f64>, PanTiltError> {
        let limbs = self.limbs(pose)?;
        self.actuation_jacobian_of(pose, &limbs)
    }

    fn actuation_jacobian_of(&self, pose: &Pointing, limbs: &[Limb; 3]) -> Result<Matrix2<f64>, PanTiltError> {
        let r7 = pose.axis();
        let ts = regular_tangents(&r7);
        let [a, b] = self.geometry.actuated;
        let j = Matrix2::new(
            limbs[a].dalpha.dot(&ts[0]),
            limbs[a].dalpha.dot(&ts[1]),
            limbs[b].dalpha.dot(&ts[0]),
            limbs[b].dalpha.dot(&ts[1]),
        );
        regular_actuation(pose, j)
    }

    /// Forward kinematics by Newton's method on the closed-form IK in the regular coordinates
    /// s = (r₇ₓ, r₇ᵧ), started from `start` (the home pose if `None`), so the solution found is
    /// the assembly continuous from the start. Returns γ, φ (φ = 0 at γ = 0). Converges when the
    /// IK residual is below 1e-14 rad.
    pub fn forward_kinematics(&self, theta: [f64; 2], start: Option<Pointing>) -> Result<Pointing, PanTiltError> {
        const MAX_ITER: usize = 50;
        let start = start.unwrap_or(Pointing { gamma: 0.0, phi: 0.0 });
        let r0 = start.axis();
        let mut s = Vector2::new(r0.x, r0.y);
        let target = Vector2::new(theta[0], theta[1]);
        let fail = |iterations: usize, residual: f64, reason: &str| PanTiltError::NoConvergence {
            theta_deg: theta.map(f64::to_degrees),
            iterations,
            residual,
            reason: reason.to_string(),
        };
        let mut residual = f64::INFINITY;
        for it in 0..MAX_ITER {
            let pose = Self::pose_of(&s)
                .ok_or_else(|| fail(it, residual, "the iterate left the upper hemisphere (γ ≥ 90°)"))?;
            let limbs = self.limbs(&pose).map_err(|e| fail(it, residual, &e.to_string()))?;
            let [a, b] = self.geometry.actuated;
            let f = Vector2::new(
                wrap(limbs[a].alpha - self.beta - target[0]),
                wrap(limbs[b].alpha - self.beta - target[1]),
            );
            residual = f.amax();
            if residual < 1e-14 {
                return Ok(pose);
            }
            let j = self
                .actuation_jacobian_of(&pose, &limbs)
                .map_err(|e| fail(it, residual, &e.to_string()))?;
            let step = j
                .try_inverse()
                .ok_or_else(|| fail(it, residual, "singular Newton matrix"))?
                * f;
            if step.amax() < 1e-16 && residual < 1e-12 {
                // Round-off floor: the Newton step no longer moves the iterate.
                return Ok(pose);
            }
            s -= step;
        }
        Err(fail(MAX_ITER, residual, "iteration limit"))
    }

    /// Pose of the regular coordinates s = (r₇ₓ, r₇ᵧ), `None` outside the open upper hemisphere.
    fn pose_of(s: &Vector2<f64>) -> Option<Pointing> {
        let n2 = s.norm_squared();
        if !n2.is_finite() || n2 >= 1.0 {
            return None;
        }
        let sg = n2.sqrt();
        let gamma = sg.atan2((1.0 - n2).sqrt());
        let phi = if sg > 0.0 { s.y.atan2(s.x) } else { 0.0 };
        Some(Pointing { gamma, phi })
    }

    /// Joint rotations, joint rates and quasi-static actuator torques at one path sample.
    pub fn path_state(&self, sample: &PathSample, springs: &JointSprings) -> Result<PathState, PanTiltError> {
        let js = self.joint_state(&sample.pose)?;
        let [a, b] = self.geometry.actuated;
        let jac = regular_actuation(
            &sample.pose,
            Matrix2::new(js.grad_s[a][0], js.grad_s[a][1], js.grad_s[b][0], js.grad_s[b][1]),
        )?;
        let det = jac.determinant();
        let xdot = Vector2::new(sample.gamma_rate, sample.phi_rate);
        let mut q_rate = [0.0; JOINTS];
        let mut gk = Vector2::zeros();
        let mut gd = Vector2::zeros();
        for (i, rate) in q_rate.iter_mut().enumerate() {
            *rate = js.grad_x[i].dot(&xdot);
            gk += js.grad_s[i] * (springs.stiffness[i] * js.q[i]);
            gd += js.grad_s[i] * (springs.damping[i] * *rate);
        }
        // τ = J_s⁻ᵀ G_sᵀ f: solve J_sᵀ τ = G_sᵀ f.
        let jt_inv = Matrix2::new(jac[(1, 1)], -jac[(1, 0)], -jac[(0, 1)], jac[(0, 0)]) / det;
        let tk = jt_inv * gk;
        let td = jt_inv * gd;
        Ok(PathState {
            sample: *sample,
            q: js.q,
            q_rate,
            torque_stiffness: [tk[0], tk[1]],
            torque_damping: [td[0], td[1]],
            det_actuation: det,
        })
    }

    /// [`PanTilt::path_state`] at every sample; stops at the first failing sample.
    pub fn path(&self, samples: &[PathSample], springs: &JointSprings) -> Result<Vec<PathState>, PanTiltError> {
        samples.iter().map(|s| self.path_state(s, springs)).collect()
    }
}
