//! The `sweep` case: a base case and the values to vary (full factorial).

use super::error::CaseError;
use serde::Deserialize;
use serde_json::{Map, Value};

/// One varied parameter: a list of values, or an evenly spaced range.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(untagged)]
pub enum VarySpec {
    /// Explicit values (numbers, strings, objects…), at least one.
    #[schemars(extend("minItems" = 1))]
    List(Vec<Value>),
    /// `steps` values from `from` to `to`, ends included.
    Range {
        /// First value.
        from: f64,
        /// Last value.
        to: f64,
        /// Number of values, 1 … 1000000 (1 gives `from`).
        #[schemars(range(min = 1, max = 1000000))]
        steps: usize,
    },
}

/// `"analysis": "sweep"`.
#[derive(Debug, Clone, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SweepCase {
    /// The case every design starts from: a case object of any analysis but `sweep`. Each
    /// design (`base` with the varied values set) is validated as a case of its own.
    #[schemars(schema_with = "base_schema")]
    pub base: Value,
    /// Dotted paths into `base` → values; the designs are every combination, the last path
    /// varying fastest. At least one path.
    #[schemars(with = "std::collections::BTreeMap<String, VarySpec>")]
    #[schemars(extend("minProperties" = 1))]
    pub vary: Map<String, Value>,
}

/// The fields of a [`VarySpec::Range`].
const RANGE_KEYS: [&str; 3] = ["from", "to", "steps"];

/// Most designs one sweep may have.
pub const MAX_DESIGNS: usize = 100_000_000;

/// The number of designs of axes with these numbers of values; `None` on overflow.
pub fn design_count(sizes: impl IntoIterator<Item = usize>) -> Option<usize> {
    sizes.into_iter().try_fold(1usize, usize::checked_mul)
}

/// A sweep ready to enumerate.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// The base case.
    pub base: Value,
    /// (dotted path, its values) in file order.
    pub axes: Vec<(String, Vec<Value>)>,
}

impl Sweep {
    /// Number of designs (built sweeps hold at most [`MAX_DESIGNS`]; saturates otherwise).
    pub fn len(&self) -> usize {
        design_count(self.axes.iter().map(|(_, v)| v.len())).unwrap_or(usize::MAX)
    }

    /// True when there is no design.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The value index on each axis of design `index` (row-major, the last axis fastest), into
    /// `picks` (one per axis).
    pub fn picks(&self, mut index: usize, picks: &mut [usize]) {
        for (k, (_, vals)) in self.axes.iter().enumerate().rev() {
            picks[k] = index % vals.len();
            index /= vals.len();
        }
    }

    /// The parameters of design `index` (path → value), in axis order.
    pub fn params(&self, index: usize) -> Map<String, Value> {
        let mut picks = vec![0; self.axes.len()];
        self.picks(index, &mut picks);
        self.axes
            .iter()
            .zip(picks)
            .map(|((p, vals), i)| (p.clone(), vals[i].clone()))
            .collect()
    }

    /// The case of design `index`: `base` with every varied path set.
    pub fn design(&self, index: usize) -> Result<Value, CaseError> {
        let mut v = self.base.clone();
        for (path, val) in self.params(index) {
            set_path(&mut v, &path, val).map_err(|m| CaseError::new(format!("vary.{path}"), m))?;
        }
        Ok(v)
    }
}

/// Sets `value` at a dotted path (`hinge.t`, `load_cases.0.name`); the parent must exist,
/// except a case's `parameters` object, created for `parameters.NAME` (a parameter the mesh
/// file declares, overridden by the case).
pub fn set_path(root: &mut Value, path: &str, value: Value) -> Result<(), String> {
    let parts: Vec<&str> = path.split('.').collect();
    let mut cur = root;
    for (depth, part) in parts.iter().enumerate() {
        let last = depth + 1 == parts.len();
        cur = match cur {
            Value::Object(m) => {
                if last {
                    m.insert(part.to_string(), value);
                    return Ok(());
                }
                if depth == 0 && *part == "parameters" && !m.contains_key("parameters") {
                    m.insert("parameters".into(), Value::Object(Map::new()));
                }
                m.get_mut(*part)
                    .ok_or_else(|| format!("`{}` does not exist in the base case", parts[..=depth].join(".")))?
            }
            Value::Array(a) => {
                let i: usize = part
                    .parse()
                    .map_err(|_| format!("`{part}` must be an index into an array"))?;
                let n = a.len();
                let slot = a
                    .get_mut(i)
                    .ok_or_else(|| format!("index {i} is out of range (array of {n})"))?;
                if last {
                    *slot = value;
                    return Ok(());
                }
                slot
            }
            _ => return Err(format!("`{}` is not an object or array", parts[..depth].join("."))),
        };
    }
    Err("empty path".into())
}

impl SweepCase {
    /// Validates the axes (the designs themselves are validated one by one when run).
    pub fn build(&self) -> Result<Sweep, CaseError> {
        if !self.base.is_object() {
            return Err(CaseError::value(
                "base",
                super::short(&self.base),
                "must be a case object",
            ));
        }
        if self.base.get("analysis").and_then(Value::as_str) == Some("sweep") {
            return Err(CaseError::value(
                "base.analysis",
                "\"sweep\"",
                "a sweep cannot vary another sweep",
            ));
        }
        if self.vary.is_empty() {
            return Err(CaseError::new("vary", "give at least one parameter to vary"));
        }
        // Parse every axis and count the designs before expanding any range, so a small file
        // asking for an astronomical sweep is refused without allocating it.
        let mut specs = Vec::with_capacity(self.vary.len());
        for (path, spec) in &self.vary {
            let p = format!("vary.{path}");
            if let Some(inner) = self
                .vary
                .keys()
                .find(|q| path.starts_with(q.as_str()) && path[q.len()..].starts_with('.'))
            {
                return Err(CaseError::value(
                    &p,
                    format!("\"{path}\""),
                    format!("it lies inside `vary.{inner}`, which sets the whole of `{inner}`: the two would overwrite each other; vary either the whole or its parts"),
                ));
            }
            if let Value::Object(m) = spec {
                if let Some(k) = m.keys().find(|k| !RANGE_KEYS.contains(&k.as_str())) {
                    return Err(CaseError::new(
                        format!("{p}.{k}"),
                        format!("unknown field `{k}` of a range; a varied path takes a list of values or {{\"from\", \"to\", \"steps\"}}"),
                    ));
                }
            }
            let spec: VarySpec = super::from_value(spec.clone(), &p)?;
            match &spec {
                VarySpec::List(v) if v.is_empty() => return Err(CaseError::new(p, "the list of values is empty")),
                VarySpec::List(_) => {}
                VarySpec::Range { from, to, steps } => {
                    if !(from.is_finite() && to.is_finite()) {
                        return Err(CaseError::value(
                            p,
                            format!("{from}..{to}"),
                            "range ends must be finite",
                        ));
                    }
                    if *steps == 0 || *steps > 1_000_000 {
                        return Err(CaseError::value(format!("{p}.steps"), steps, "must be in 1..=1000000"));
                    }
                }
            }
            specs.push((path, p, spec));
        }
        let count = design_count(specs.iter().map(|(_, _, s)| match s {
            VarySpec::List(v) => v.len(),
            VarySpec::Range { steps, .. } => *steps,
        }));
        match count {
            Some(n) if n <= MAX_DESIGNS => {}
            _ => {
                let sizes: Vec<String> = specs
                    .iter()
                    .map(|(_, _, s)| match s {
                        VarySpec::List(v) => v.len().to_string(),
                        VarySpec::Range { steps, .. } => steps.to_string(),
                    })
                    .collect();
                let total = count.map_or_else(|| "more than 2^64".to_string(), |n| n.to_string());
                return Err(CaseError::value(
                    "vary",
                    format!("{} = {total} designs", sizes.join(" × ")),
                    "a sweep may have at most 100 000 000 designs",
                ));
            }
        }
        let mut axes = Vec::with_capacity(specs.len());
        for (path, p, spec) in specs {
            let vals = match spec {
                VarySpec::List(v) => v,
                VarySpec::Range { from, to, steps } => (0..steps)
                    .map(|k| {
                        let x = if steps == 1 {
                            from
                        } else {
                            from + (to - from) * k as f64 / (steps - 1) as f64
                        };
                        Value::from(x)
                    })
                    .collect(),
            };
            let mut probe = self.base.clone();
            set_path(&mut probe, path, vals[0].clone()).map_err(|m| CaseError::new(p.clone(), m))?;
            axes.push((path.clone(), vals));
        }
        let sweep = Sweep {
            base: self.base.clone(),
            axes,
        };
        Ok(sweep)
    }
}

/// The name under `$defs` of the schema of the kinds a sweep's `base` may be (any but `sweep`):
/// the list of kinds lives with the analyses, whose case-file schema defines it.
pub const BASE_KIND_DEF: &str = "SweepBaseAnalysis";

/// Schema of `base`: an object whose `analysis` is any but `sweep` (the rest is checked per
/// design, since varied values may complete it).
fn base_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    schemars::json_schema!({
        "type": "object",
        "required": ["analysis"],
        "properties": {"analysis": {"$ref": format!("#/$defs/{BASE_KIND_DEF}")}}
    })
}
