//! A forward-mode dual number v + d·ε (ε² = 0): a value and its derivative along one
//! direction, carried through the hinge's flexibility integrals by the chain rule (exact: no
//! difference quotient).

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value `v` and its derivative `d` along the direction of differentiation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dual {
    /// Value.
    pub v: f64,
    /// Derivative along the direction.
    pub d: f64,
}

impl Dual {
    /// A value with derivative `d`.
    pub const fn new(v: f64, d: f64) -> Dual {
        Dual { v, d }
    }

    /// A constant (zero derivative).
    pub const fn c(v: f64) -> Dual {
        Dual { v, d: 0.0 }
    }

    /// √x; a zero derivative stays zero where √ has none (x = 0).
    pub fn sqrt(self) -> Dual {
        let s = self.v.sqrt();
        Dual::new(s, if self.d == 0.0 { 0.0 } else { self.d / (2.0 * s) })
    }

    /// ln x.
    pub fn ln(self) -> Dual {
        Dual::new(self.v.ln(), self.d / self.v)
    }

    /// eˣ.
    pub fn exp(self) -> Dual {
        let e = self.v.exp();
        Dual::new(e, e * self.d)
    }

    /// sin x.
    pub fn sin(self) -> Dual {
        Dual::new(self.v.sin(), self.v.cos() * self.d)
    }

    /// cos x.
    pub fn cos(self) -> Dual {
        Dual::new(self.v.cos(), -self.v.sin() * self.d)
    }

    /// tan x.
    pub fn tan(self) -> Dual {
        let t = self.v.tan();
        Dual::new(t, (1.0 + t * t) * self.d)
    }

    /// atan x.
    pub fn atan(self) -> Dual {
        Dual::new(self.v.atan(), self.d / (1.0 + self.v * self.v))
    }

    /// asin x; a zero derivative stays zero at |x| = 1 (a clamped argument).
    pub fn asin(self) -> Dual {
        let d = if self.d == 0.0 {
            0.0
        } else {
            self.d / (1.0 - self.v * self.v).sqrt()
        };
        Dual::new(self.v.asin(), d)
    }

    /// acos x.
    pub fn acos(self) -> Dual {
        let d = if self.d == 0.0 {
            0.0
        } else {
            -self.d / (1.0 - self.v * self.v).sqrt()
        };
        Dual::new(self.v.acos(), d)
    }

    /// xᵖ for a constant p.
    pub fn powf(self, p: f64) -> Dual {
        let y = self.v.powf(p);
        Dual::new(
            y,
            if self.d == 0.0 {
                0.0
            } else {
                p * self.v.powf(p - 1.0) * self.d
            },
        )
    }

    /// |x|.
    pub fn abs(self) -> Dual {
        if self.v < 0.0 {
            -self
        } else {
            self
        }
    }

    /// The smaller by value (the derivative of the branch taken; `self` on a tie).
    pub fn min(self, o: Dual) -> Dual {
        if o.v < self.v {
            o
        } else {
            self
        }
    }

    /// The larger by value (`self` on a tie).
    pub fn max(self, o: Dual) -> Dual {
        if o.v > self.v {
            o
        } else {
            self
        }
    }

    /// Clamped to [lo, hi]: a constant where clamped.
    pub fn clamp(self, lo: f64, hi: f64) -> Dual {
        if self.v <= lo {
            Dual::c(lo)
        } else if self.v >= hi {
            Dual::c(hi)
        } else {
            self
        }
    }
}

impl From<f64> for Dual {
    fn from(v: f64) -> Dual {
        Dual::c(v)
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual::new(self.v + o.v, self.d + o.d)
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual::new(self.v - o.v, self.d - o.d)
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        Dual::new(self.v * o.v, self.d * o.v + self.v * o.d)
    }
}

impl Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        let q = self.v / o.v;
        Dual::new(q, (self.d - q * o.d) / o.v)
    }
}

impl Neg for Dual {
    type Output = Dual;
    fn neg(self) -> Dual {
        Dual::new(-self.v, -self.d)
    }
}

impl Add<f64> for Dual {
    type Output = Dual;
    fn add(self, o: f64) -> Dual {
        Dual::new(self.v + o, self.d)
    }
}

impl Sub<f64> for Dual {
    type Output = Dual;
    fn sub(self, o: f64) -> Dual {
        Dual::new(self.v - o, self.d)
    }
}

impl Mul<f64> for Dual {
    type Output = Dual;
    fn mul(self, o: f64) -> Dual {
        Dual::new(self.v * o, self.d * o)
    }
}

impl Div<f64> for Dual {
    type Output = Dual;
    fn div(self, o: f64) -> Dual {
        Dual::new(self.v / o, self.d / o)
    }
}

impl Add<Dual> for f64 {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        o + self
    }
}

impl Sub<Dual> for f64 {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual::new(self - o.v, -o.d)
    }
}

impl Mul<Dual> for f64 {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        o * self
    }
}

impl Div<Dual> for f64 {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        Dual::c(self) / o
    }
}
