//! Arithmetic expressions of case parameters: `"2*$R + 5"`, `"$L/2"`, `"-sqrt($a*$a + 1)"`,
//! `"$r*cos(30)"`.
//!
//! Grammar (recursive descent, usual precedence, left-associative binary operators):
//!
//! ```text
//! sum     = product { ("+" | "-") product }
//! product = unary { ("*" | "/") unary }
//! unary   = ("-" | "+") unary | primary
//! primary = NUMBER | "$" NAME | FUNC "(" sum ")" | "(" sum ")"
//! FUNC    = sqrt | sin | cos          (sin, cos of an angle in degrees)
//! NAME    = letter or "_", then letters, digits or "_"
//! ```
//!
//! An expression is parsed once into an [`Expr`] and evaluated for any parameter values
//! ([`Expr::eval`]), so a case can be re-resolved for new values without parsing again.

use std::fmt;

/// A parsed expression.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// A literal number.
    Num(f64),
    /// `$NAME`.
    Param(String),
    /// `-x`.
    Neg(Box<Expr>),
    /// `x op y`.
    Bin(Op, Box<Expr>, Box<Expr>),
    /// `f(x)`.
    Call(Func, Box<Expr>),
}

/// A value and its derivative along a direction ([`Expr::eval_tangent`]).
pub type Dual = (f64, f64);

/// A binary operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
}

/// A function of one argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// Square root (argument ≥ 0).
    Sqrt,
    /// Sine of an angle in degrees.
    Sin,
    /// Cosine of an angle in degrees.
    Cos,
}

/// Why an expression could not be parsed or evaluated.
#[derive(Debug, Clone, PartialEq)]
pub enum ExprError {
    /// Not an expression of the grammar: what was expected at character `at` (0-based).
    Syntax {
        /// Character offset of the problem.
        at: usize,
        /// What was found and what was expected.
        message: String,
    },
    /// `x / 0`.
    DivisionByZero,
    /// `sqrt` of a negative number.
    NegativeSqrt(f64),
    /// A result that is not a finite number (overflow).
    NonFinite,
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExprError::Syntax { at, message } => write!(f, "syntax error at character {}: {message}", at + 1),
            ExprError::DivisionByZero => write!(f, "division by zero"),
            ExprError::NegativeSqrt(x) => write!(f, "sqrt of the negative number {x}"),
            ExprError::NonFinite => write!(f, "the result is not a finite number (overflow)"),
        }
    }
}

/// True for a valid parameter name (see the grammar's NAME).
pub fn is_name(s: &str) -> bool {
    let mut c = s.chars();
    c.next().is_some_and(|f| f.is_ascii_alphabetic() || f == '_') && c.all(|x| x.is_ascii_alphanumeric() || x == '_')
}

impl Expr {
    /// Parses `text` (see the module docs).
    pub fn parse(text: &str) -> Result<Expr, ExprError> {
        let mut p = Parser {
            s: text.as_bytes(),
            i: 0,
        };
        let e = p.sum()?;
        p.skip_space();
        if p.i < p.s.len() {
            return Err(p.error(format!("unexpected `{}` after a complete expression", p.rest_char())));
        }
        Ok(e)
    }

    /// The value, with `lookup` giving each parameter's value (its errors pass through).
    /// Every intermediate result is checked: a division by zero, the square root of a
    /// negative number or an overflow is an error, never NaN or ∞.
    pub fn eval<E: From<ExprError>>(&self, lookup: &mut dyn FnMut(&str) -> Result<f64, E>) -> Result<f64, E> {
        let v = match self {
            Expr::Num(x) => *x,
            Expr::Param(name) => lookup(name)?,
            Expr::Neg(x) => -x.eval(lookup)?,
            Expr::Bin(op, a, b) => {
                let (a, b) = (a.eval(lookup)?, b.eval(lookup)?);
                match op {
                    Op::Add => a + b,
                    Op::Sub => a - b,
                    Op::Mul => a * b,
                    Op::Div if b == 0.0 => return Err(ExprError::DivisionByZero.into()),
                    Op::Div => a / b,
                }
            }
            Expr::Call(f, x) => {
                let x = x.eval(lookup)?;
                match f {
                    Func::Sqrt if x < 0.0 => return Err(ExprError::NegativeSqrt(x).into()),
                    Func::Sqrt => x.sqrt(),
                    Func::Sin => x.to_radians().sin(),
                    Func::Cos => x.to_radians().cos(),
                }
            }
        };
        if v.is_finite() {
            Ok(v)
        } else {
            Err(ExprError::NonFinite.into())
        }
    }

    /// The value and its derivative along a direction in parameter space (forward-mode
    /// automatic differentiation, dual numbers): `lookup` gives each parameter's value and
    /// derivative. d sin(x°) = (π/180) cos(x°) dx; d sqrt(x) = dx / (2 sqrt x), refused at
    /// x = 0 when dx ≠ 0 (an infinite derivative, [`ExprError::NonFinite`]). Errors as
    /// [`Self::eval`].
    pub fn eval_tangent<E: From<ExprError>>(&self, lookup: &mut dyn FnMut(&str) -> Result<Dual, E>) -> Result<Dual, E> {
        let (v, d) = match self {
            Expr::Num(x) => (*x, 0.0),
            Expr::Param(name) => lookup(name)?,
            Expr::Neg(x) => {
                let (v, d) = x.eval_tangent(lookup)?;
                (-v, -d)
            }
            Expr::Bin(op, a, b) => {
                let ((a, da), (b, db)) = (a.eval_tangent(lookup)?, b.eval_tangent(lookup)?);
                match op {
                    Op::Add => (a + b, da + db),
                    Op::Sub => (a - b, da - db),
                    Op::Mul => (a * b, da * b + a * db),
                    Op::Div if b == 0.0 => return Err(ExprError::DivisionByZero.into()),
                    Op::Div => (a / b, (da * b - a * db) / (b * b)),
                }
            }
            Expr::Call(f, x) => {
                let (x, dx) = x.eval_tangent(lookup)?;
                let rad = std::f64::consts::PI / 180.0;
                match f {
                    Func::Sqrt if x < 0.0 => return Err(ExprError::NegativeSqrt(x).into()),
                    Func::Sqrt if dx == 0.0 => (x.sqrt(), 0.0),
                    Func::Sqrt => (x.sqrt(), dx / (2.0 * x.sqrt())),
                    Func::Sin => (x.to_radians().sin(), rad * x.to_radians().cos() * dx),
                    Func::Cos => (x.to_radians().cos(), -rad * x.to_radians().sin() * dx),
                }
            }
        };
        if v.is_finite() && d.is_finite() {
            Ok((v, d))
        } else {
            Err(ExprError::NonFinite.into())
        }
    }

    /// The parameter names the expression uses, in order of appearance (repeats included).
    pub fn names<'a>(&'a self, out: &mut Vec<&'a str>) {
        match self {
            Expr::Num(_) => {}
            Expr::Param(n) => out.push(n),
            Expr::Neg(x) | Expr::Call(_, x) => x.names(out),
            Expr::Bin(_, a, b) => {
                a.names(out);
                b.names(out);
            }
        }
    }
}

struct Parser<'s> {
    s: &'s [u8],
    i: usize,
}

impl Parser<'_> {
    fn error(&self, message: String) -> ExprError {
        ExprError::Syntax { at: self.i, message }
    }

    fn rest_char(&self) -> char {
        std::str::from_utf8(&self.s[self.i..])
            .ok()
            .and_then(|r| r.chars().next())
            .unwrap_or('?')
    }

    fn skip_space(&mut self) {
        while self.s.get(self.i).is_some_and(u8::is_ascii_whitespace) {
            self.i += 1;
        }
    }

    /// The next non-space byte, consumed if it is one of `ops`.
    fn take(&mut self, ops: &[u8]) -> Option<u8> {
        self.skip_space();
        let c = *self.s.get(self.i)?;
        ops.contains(&c).then(|| {
            self.i += 1;
            c
        })
    }

    fn sum(&mut self) -> Result<Expr, ExprError> {
        let mut e = self.product()?;
        while let Some(c) = self.take(b"+-") {
            let op = if c == b'+' { Op::Add } else { Op::Sub };
            e = Expr::Bin(op, Box::new(e), Box::new(self.product()?));
        }
        Ok(e)
    }

    fn product(&mut self) -> Result<Expr, ExprError> {
        let mut e = self.unary()?;
        while let Some(c) = self.take(b"*/") {
            let op = if c == b'*' { Op::Mul } else { Op::Div };
            e = Expr::Bin(op, Box::new(e), Box::new(self.unary()?));
        }
        Ok(e)
    }

    fn unary(&mut self) -> Result<Expr, ExprError> {
        match self.take(b"-+") {
            Some(b'-') => Ok(Expr::Neg(Box::new(self.unary()?))),
            Some(_) => self.unary(),
            None => self.primary(),
        }
    }

    fn word(&mut self) -> &str {
        let start = self.i;
        while self
            .s
            .get(self.i)
            .is_some_and(|c| c.is_ascii_alphanumeric() || *c == b'_')
        {
            self.i += 1;
        }
        std::str::from_utf8(&self.s[start..self.i]).unwrap_or("")
    }

    fn primary(&mut self) -> Result<Expr, ExprError> {
        self.skip_space();
        let Some(&c) = self.s.get(self.i) else {
            return Err(
                self.error("the expression ends where a number, `$NAME`, `(` or a function was expected".into())
            );
        };
        match c {
            b'(' => {
                self.i += 1;
                let e = self.sum()?;
                self.close()?;
                Ok(e)
            }
            b'$' => {
                self.i += 1;
                let at = self.i;
                let name = self.word().to_string();
                if !is_name(&name) {
                    self.i = at;
                    return Err(self.error(
                        "`$` must be followed by a parameter name (a letter or `_`, then letters, digits or `_`)"
                            .into(),
                    ));
                }
                Ok(Expr::Param(name))
            }
            b'0'..=b'9' | b'.' => self.number(),
            c if c.is_ascii_alphabetic() => {
                let at = self.i;
                let f = match self.word() {
                    "sqrt" => Func::Sqrt,
                    "sin" => Func::Sin,
                    "cos" => Func::Cos,
                    w => {
                        let w = w.to_string();
                        self.i = at;
                        return Err(self.error(format!(
                            "unknown function `{w}` (functions: sqrt, sin, cos in degrees; parameters are written `$NAME`)"
                        )));
                    }
                };
                if self.take(b"(").is_none() {
                    return Err(self.error("`(` expected after the function name".into()));
                }
                let arg = self.sum()?;
                self.close()?;
                Ok(Expr::Call(f, Box::new(arg)))
            }
            _ => Err(self.error(format!(
                "unexpected `{}` where a number, `$NAME`, `(` or a function was expected",
                self.rest_char()
            ))),
        }
    }

    fn close(&mut self) -> Result<(), ExprError> {
        match self.take(b")") {
            Some(_) => Ok(()),
            None => Err(self.error("`)` expected".into())),
        }
    }

    fn number(&mut self) -> Result<Expr, ExprError> {
        let start = self.i;
        let digits = |p: &mut Self| {
            while p.s.get(p.i).is_some_and(u8::is_ascii_digit) {
                p.i += 1;
            }
        };
        digits(self);
        if self.s.get(self.i) == Some(&b'.') {
            self.i += 1;
            digits(self);
        }
        if matches!(self.s.get(self.i), Some(b'e' | b'E')) {
            self.i += 1;
            if matches!(self.s.get(self.i), Some(b'+' | b'-')) {
                self.i += 1;
            }
            digits(self);
        }
        let text = std::str::from_utf8(&self.s[start..self.i]).unwrap_or("");
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Expr::Num(x)),
            _ => {
                self.i = start;
                Err(self.error(format!("`{text}` is not a number")))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval(text: &str, vars: &[(&str, f64)]) -> Result<f64, ExprError> {
        let e = Expr::parse(text)?;
        e.eval(&mut |n: &str| -> Result<f64, ExprError> {
            Ok(vars
                .iter()
                .find(|(k, _)| *k == n)
                .map(|(_, v)| *v)
                .expect("test names its parameters"))
        })
    }

    /// Precedence and associativity as in arithmetic: `*` `/` before `+` `-`, left to right.
    #[test]
    fn precedence_and_associativity() {
        assert_eq!(eval("2*3 + 5", &[]), Ok(11.0));
        assert_eq!(eval("2 + 3*5", &[]), Ok(17.0));
        assert_eq!(eval("(2 + 3)*5", &[]), Ok(25.0));
        assert_eq!(eval("10 - 4 - 3", &[]), Ok(3.0));
        assert_eq!(eval("24/4/3", &[]), Ok(2.0));
        assert_eq!(eval("2*$R + 5", &[("R", 4.5)]), Ok(14.0));
        assert_eq!(eval("$L/2", &[("L", 60.0)]), Ok(30.0));
        assert_eq!(eval("1.5e2 + .5 + 2E-1", &[]), Ok(150.7));
    }

    /// Unary minus binds tighter than `*` and may repeat: `-2*3` = −6, `--2` = 2, `2*-$a`.
    #[test]
    fn unary_minus() {
        assert_eq!(eval("-2*3", &[]), Ok(-6.0));
        assert_eq!(eval("--2", &[]), Ok(2.0));
        assert_eq!(eval("2*-$a", &[("a", 1.5)]), Ok(-3.0));
        assert_eq!(eval("-(1 - 4)", &[]), Ok(3.0));
        assert_eq!(eval("+3 - -1", &[]), Ok(4.0));
    }

    /// sin and cos take degrees: sin 30° = 1/2, cos 60° = 1/2, cos 180° = −1; sqrt 2.
    #[test]
    fn functions_in_degrees() {
        let near = |r: Result<f64, ExprError>, want: f64| (r.unwrap() - want).abs() < 1e-15;
        assert!(near(eval("sin(30)", &[]), 0.5));
        assert!(near(eval("cos(60)", &[]), 0.5));
        assert!(near(eval("cos(180)", &[]), -1.0));
        assert!(near(eval("2*sin($a/2)", &[("a", 60.0)]), 1.0));
        assert_eq!(eval("sqrt(16) + sqrt($x)", &[("x", 2.0)]), Ok(4.0 + 2f64.sqrt()));
    }

    /// Each error kind, with the position of a syntax error.
    #[test]
    fn errors() {
        assert_eq!(eval("1/($a - 2)", &[("a", 2.0)]), Err(ExprError::DivisionByZero));
        assert_eq!(eval("sqrt(-4)", &[]), Err(ExprError::NegativeSqrt(-4.0)));
        assert_eq!(eval("1e300*1e300", &[]), Err(ExprError::NonFinite));
        let at = |text: &str| match Expr::parse(text) {
            Err(ExprError::Syntax { at, .. }) => at,
            other => panic!("{text}: {other:?}"),
        };
        assert_eq!(at("2*$R +"), 6);
        assert_eq!(at("(1 + 2"), 6);
        assert_eq!(at("1 + 2)"), 5);
        assert_eq!(at("2 $a"), 2);
        assert_eq!(at("$ + 1"), 1);
        assert_eq!(at("$1a"), 1);
        assert_eq!(at("tan(3)"), 0);
        assert_eq!(at("sqrt 3"), 5);
        assert_eq!(at(""), 0);
        assert_eq!(at("1.2.3"), 3);
    }

    /// The names an expression uses, in order.
    #[test]
    fn names_in_order() {
        let e = Expr::parse("$a*sqrt($b) - $a").unwrap();
        let mut names = Vec::new();
        e.names(&mut names);
        assert_eq!(names, ["a", "b", "a"]);
        assert!(is_name("t_rev2") && !is_name("2t") && !is_name("") && !is_name("a-b"));
    }
}
