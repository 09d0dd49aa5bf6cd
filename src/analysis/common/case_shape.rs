//! The check that refuses an array where the case schema allows only an object.
//!
//! serde also reads a struct from the array of its field values in declaration order
//! (`"leg": [10, 10]`, `"hinge": ["leaf", 5, 1, …]`). Case files do not take that form: the schema
//! refuses it, and the errors about such a value would name fields (`hinge.t`) that the file
//! does not have.
//!
//! The JSON Schema of case files is compiled once into a graph of [`Shape`]s: each stands for
//! the set of schema nodes a value at some place may match (what `$ref`, `anyOf`, `oneOf` and
//! `allOf` lead to; `if`/`then`/`else` and `not` only add constraints), with its children by
//! field name and array position. Checking a case is then one walk over its value: a vector
//! index per array item, a binary search per object field among a few sorted names, and no
//! allocation unless there is an error; a subtree that cannot hold a refused array is skipped.

use crate::case::{short, CaseError};
use serde_json::{Map, Value};
use std::collections::HashMap;
use std::sync::OnceLock;

type Id = usize;

/// The compiled schema of the places of a case value that may match one set of schema nodes.
#[derive(Debug, Default)]
struct Shape {
    /// Some schema node of the set accepts an array (or the set is empty: nothing is known).
    allows_array: bool,
    /// An array somewhere at or below this place could be refused (else the walk skips it).
    can_refuse: bool,
    /// Array items by position (`prefixItems`), then every later item.
    prefix: Vec<Id>,
    rest: Id,
    /// Object fields by name (sorted), then any other field (`additionalProperties`).
    fields: Vec<(String, Id)>,
    other: Id,
}

/// The shape graph; shape 0 is the empty set (nothing known, nothing refused).
struct Shapes {
    shapes: Vec<Shape>,
    root: Id,
}

/// Refuses an array where the case schema allows only an object (see the module docs). `schema`
/// gives the case schema; it is called once per process, when the shape graph is compiled.
pub fn refuse_positional(value: &Value, schema: fn() -> Value) -> Result<(), CaseError> {
    static SHAPES: OnceLock<Shapes> = OnceLock::new();
    let s = SHAPES.get_or_init(|| compile(&schema()));
    let mut steps = Vec::new();
    walk(value, s.root, &s.shapes, &mut steps)
}

#[derive(Clone, Copy)]
enum Step<'v> {
    Key(&'v str),
    Index(usize),
}

fn path_of(steps: &[Step]) -> String {
    let mut p = String::new();
    for s in steps {
        match s {
            Step::Key(k) if p.is_empty() => p.push_str(k),
            Step::Key(k) => {
                p.push('.');
                p.push_str(k);
            }
            Step::Index(i) => p.push_str(&format!("[{i}]")),
        }
    }
    if p.is_empty() {
        ".".into()
    } else {
        p
    }
}

fn walk<'v>(value: &'v Value, id: Id, shapes: &[Shape], steps: &mut Vec<Step<'v>>) -> Result<(), CaseError> {
    let shape = &shapes[id];
    if !shape.can_refuse {
        return Ok(());
    }
    match value {
        Value::Array(items) => {
            if !shape.allows_array {
                return Err(CaseError::value(
                    path_of(steps),
                    short(value),
                    "an object is expected here: give its fields by name, {\"field\": value, …}",
                ));
            }
            for (i, item) in items.iter().enumerate() {
                steps.push(Step::Index(i));
                walk(item, shape.prefix.get(i).copied().unwrap_or(shape.rest), shapes, steps)?;
                steps.pop();
            }
        }
        Value::Object(map) => {
            for (k, item) in map {
                let child = match shape.fields.binary_search_by(|(name, _)| name.as_str().cmp(k)) {
                    Ok(j) => shape.fields[j].1,
                    Err(_) => shape.other,
                };
                steps.push(Step::Key(k));
                walk(item, child, shapes, steps)?;
                steps.pop();
            }
        }
        _ => {}
    }
    Ok(())
}

/// The schema nodes that `node` stands for: itself if it says something about types, and what
/// its `$ref`, `anyOf`, `oneOf` and `allOf` lead to.
fn expand<'a>(node: &'a Value, defs: Option<&'a Map<String, Value>>, out: &mut Vec<&'a Value>, depth: usize) {
    let Some(m) = node.as_object() else {
        return;
    };
    if depth > 32 {
        return;
    }
    let typed = [
        "type",
        "properties",
        "additionalProperties",
        "items",
        "prefixItems",
        "enum",
        "const",
    ];
    if typed.iter().any(|k| m.contains_key(*k)) {
        out.push(node);
    }
    if let Some(r) = m.get("$ref").and_then(Value::as_str) {
        if let Some(d) = r.strip_prefix("#/$defs/").and_then(|n| defs.and_then(|d| d.get(n))) {
            expand(d, defs, out, depth + 1);
        }
    }
    for k in ["anyOf", "oneOf", "allOf"] {
        for b in m.get(k).and_then(Value::as_array).into_iter().flatten() {
            expand(b, defs, out, depth + 1);
        }
    }
}

fn allows_array(node: &Value) -> bool {
    match node.get("type") {
        Some(Value::String(t)) => t == "array",
        Some(Value::Array(ts)) => ts.iter().any(|t| t == "array"),
        _ => {
            !(node.get("properties").is_some()
                || node.get("additionalProperties").is_some_and(Value::is_object)
                || node.get("enum").is_some()
                || node.get("const").is_some())
        }
    }
}

/// Builds the shape graph of `schema` (each distinct set of schema nodes once).
fn compile(schema: &Value) -> Shapes {
    let defs = schema.get("$defs").and_then(Value::as_object);
    let mut c = Compiler {
        defs,
        shapes: vec![Shape {
            allows_array: true,
            ..Shape::default()
        }],
        ids: HashMap::new(),
        children: vec![Vec::new()],
    };
    c.ids.insert(Vec::new(), 0);
    let mut roots = Vec::new();
    expand(schema, defs, &mut roots, 0);
    let root = c.shape_of(roots);
    // `can_refuse`: the shapes that refuse an array, and every shape that reaches one.
    for (s, shape) in c.shapes.iter_mut().enumerate() {
        shape.can_refuse = s != 0 && !shape.allows_array;
    }
    loop {
        let mut changed = false;
        for s in 0..c.shapes.len() {
            if !c.shapes[s].can_refuse && c.children[s].iter().any(|&k| c.shapes[k].can_refuse) {
                c.shapes[s].can_refuse = true;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    Shapes { shapes: c.shapes, root }
}

struct Compiler<'a> {
    defs: Option<&'a Map<String, Value>>,
    shapes: Vec<Shape>,
    /// Shape of each set of schema nodes (by address, sorted).
    ids: HashMap<Vec<usize>, Id>,
    /// Every child of each shape (for `can_refuse`).
    children: Vec<Vec<Id>>,
}

impl<'a> Compiler<'a> {
    /// The shape of the schema nodes `set` (compiled on first sight).
    fn shape_of(&mut self, mut set: Vec<&'a Value>) -> Id {
        set.sort_by_key(|n| *n as *const Value as usize);
        set.dedup_by_key(|n| *n as *const Value as usize);
        let key: Vec<usize> = set.iter().map(|n| *n as *const Value as usize).collect();
        if let Some(&id) = self.ids.get(&key) {
            return id;
        }
        let id = self.shapes.len();
        self.ids.insert(key, id);
        self.shapes.push(Shape {
            allows_array: set.iter().any(|n| allows_array(n)),
            ..Shape::default()
        });
        self.children.push(Vec::new());
        // The schema nodes of a child: what `pick` gives of each node of the set, expanded.
        let child = |c: &mut Self, pick: &dyn Fn(&'a Value) -> Option<&'a Value>| {
            let mut out = Vec::new();
            for n in set.iter().filter_map(|n| pick(n)) {
                expand(n, c.defs, &mut out, 0);
            }
            c.shape_of(out)
        };
        let prefix_len = set
            .iter()
            .filter_map(|n| n.get("prefixItems").and_then(Value::as_array))
            .map(Vec::len)
            .max()
            .unwrap_or(0);
        let items = |n: &'a Value| n.get("items").filter(|x| x.is_object());
        let prefix: Vec<Id> = (0..prefix_len)
            .map(|i| {
                child(self, &|n| {
                    n.get("prefixItems").and_then(|p| p.get(i)).or_else(|| items(n))
                })
            })
            .collect();
        let rest = child(self, &items);
        let additional = |n: &'a Value| n.get("additionalProperties").filter(|x| x.is_object());
        let mut names: Vec<&'a str> = set
            .iter()
            .filter_map(|n| n.get("properties").and_then(Value::as_object))
            .flat_map(|p| p.keys().map(String::as_str))
            .collect();
        names.sort_unstable();
        names.dedup();
        let fields: Vec<(String, Id)> = names
            .into_iter()
            .map(|k| {
                let named = move |n: &'a Value| n.get("properties").and_then(|p| p.get(k)).or_else(|| additional(n));
                (k.to_string(), child(self, &named))
            })
            .collect();
        let other = child(self, &additional);
        let mut kids: Vec<Id> = prefix.iter().copied().chain([rest, other]).collect();
        kids.extend(fields.iter().map(|(_, k)| *k));
        self.children[id] = kids;
        let shape = &mut self.shapes[id];
        shape.prefix = prefix;
        shape.rest = rest;
        shape.fields = fields;
        shape.other = other;
        id
    }
}
