//! The arithmetic of one serial chain, fixed-size and allocation-free: what a mesh's chains
//! ([`super::Chain`]) condense with, and what a caller without a model (generating a chain's
//! pieces on the fly, as the stage's legs are) can condense with.
//!
//! A chain from a to b is walked link by link (element from p to q, q towards b). Its
//! compliance at b relative to clamped a sums the links' compliances carried rigidly to b,
//! C_b = Σₑ R(x_b − x_q) C_q R(x_b − x_q)ᵀ ([`Summation`]); the end force at b is
//! f_b = C_b⁻¹ (u_b − R(x_b − x_a) u_a) ([`Ends::end_force`]); statics along the unloaded chain
//! gives every link's end forces from f_b ([`Link::end_forces`]) and the motion of each inner
//! node from the one before ([`Link::carry`]) (J. S. Przemieniecki, Theory of Matrix Structural
//! Analysis, 1968, §6.5 and §9.6). Lengths mm, forces N and N·mm, compliances mm/N, rad/N,
//! rad/(N·mm), all in global axes unless named local. The functions are `#[inline]`: called
//! per piece and design, a call across codegen units cost the stage's linear solve ~10 % more
//! instructions when it used them.

use crate::fem::transform::{beam_frame, rigid_arm, t6};
use nalgebra::{Matrix6, Vector3, Vector6};

/// A flexibility element's compliance as a matrix if it is finite, symmetric (relative 1e-9)
/// and positive definite: the element's own acceptance test
/// ([`crate::fem::element::flex_tip_stiffness`]), without inverting it.
#[inline]
pub fn checked_compliance(c: &[[f64; 6]; 6]) -> Option<Matrix6<f64>> {
    let c = Matrix6::from_fn(|i, j| c[i][j]);
    let scale = c.amax();
    let ok = scale > 0.0 && scale.is_finite() && (c - c.transpose()).amax() <= 1e-9 * scale;
    (ok && c.cholesky().is_some()).then_some(c)
}

/// One element of a chain as the condensation sees it: its ends in chain order and its axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Link {
    /// The end towards a, mm.
    pub p: Vector3<f64>,
    /// The end towards b, mm.
    pub q: Vector3<f64>,
    /// T = diag(Λ, Λ): global components → the element's local axes.
    pub t: Matrix6<f64>,
}

impl Link {
    /// The link of an element from node 1 at `p` to node 2 at `q` with orientation vector
    /// `up` ([`beam_frame`]); `None` if the ends coincide or `up` is parallel to the axis.
    #[inline]
    pub fn along(p: Vector3<f64>, q: Vector3<f64>, up: Vector3<f64>) -> Option<Link> {
        let (lam, _) = beam_frame(p.into(), q.into(), up.into())?;
        Some(Link { p, q, t: t6(&lam) })
    }

    /// C_q: the element's cantilever compliance `local` (at its node 2 relative to clamped
    /// node 1, local axes) in global axes, Tᵀ C T; for an element pointing back towards a
    /// (`reversed`: node 2 at p) carried from p to q, R(x_q − x_p) Tᵀ C T R(x_q − x_p)ᵀ.
    #[inline]
    pub fn compliance(&self, local: &Matrix6<f64>, reversed: bool) -> Matrix6<f64> {
        let c_t = self.t.transpose() * local * self.t;
        if reversed {
            let r = rigid_arm(&(self.q - self.p));
            r * c_t * r.transpose()
        } else {
            c_t
        }
    }

    /// The forces on the element at p and at q (global axes) for the chain's end force `f_b`
    /// at `xb`: f_q = R(x_b − x_q)ᵀ f_b and f_p = −R(x_q − x_p)ᵀ f_q.
    #[inline]
    pub fn end_forces(&self, xb: &Vector3<f64>, f_b: &Vector6<f64>) -> (Vector6<f64>, Vector6<f64>) {
        let f_q = rigid_arm(&(xb - self.q)).transpose() * f_b;
        let f_p = -(rigid_arm(&(self.q - self.p)).transpose() * f_q);
        (f_p, f_q)
    }

    /// The motion of q from that of p and the force f_q at q: u_q = R(x_q − x_p) u_p + C_q f_q.
    #[inline]
    pub fn carry(&self, u_p: &Vector6<f64>, c_q: &Matrix6<f64>, f_q: &Vector6<f64>) -> Vector6<f64> {
        rigid_arm(&(self.q - self.p)) * u_p + c_q * f_q
    }
}

/// C_b summed link by link (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summation {
    xb: Vector3<f64>,
    c: Matrix6<f64>,
}

impl Summation {
    /// An empty sum for a chain ending at `xb`, mm.
    #[inline]
    pub fn new(xb: Vector3<f64>) -> Summation {
        Summation {
            xb,
            c: Matrix6::zeros(),
        }
    }

    /// Adds a link's compliance `c_q` (global axes) at its far end `q`.
    #[inline]
    pub fn add(&mut self, q: &Vector3<f64>, c_q: &Matrix6<f64>) {
        let r = rigid_arm(&(self.xb - q));
        self.c += r * c_q * r.transpose();
    }

    /// The condensed chain from `xa` to the sum's end; `None` if C_b is not positive definite.
    #[inline]
    pub fn ends(self, xa: Vector3<f64>) -> Option<Ends> {
        let c_b = (self.c + self.c.transpose()) * 0.5;
        let k_b = c_b.cholesky()?.inverse();
        Some(Ends {
            xa,
            xb: self.xb,
            c_b,
            k_b,
        })
    }
}

/// A chain condensed onto its end nodes: exactly one flexibility element from a to b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ends {
    /// End a, mm.
    pub xa: Vector3<f64>,
    /// End b, mm.
    pub xb: Vector3<f64>,
    /// C_b: compliance of b relative to clamped a, global axes.
    pub c_b: Matrix6<f64>,
    /// C_b⁻¹.
    pub k_b: Matrix6<f64>,
}

impl Ends {
    /// The chain's force at b (global axes) for end motions `u_a`, `u_b`:
    /// f_b = C_b⁻¹ (u_b − R(x_b − x_a) u_a).
    #[inline]
    pub fn end_force(&self, u_a: &Vector6<f64>, u_b: &Vector6<f64>) -> Vector6<f64> {
        let delta = u_b - rigid_arm(&(self.xb - self.xa)) * u_a;
        self.k_b * delta
    }
}
