//! The inner nodes of segmented hinge elements (`"segments"` > 1): numbered after the case's
//! nodes, they are hidden from a `static` result's `displacements` unless the case asks for them
//! (`"output": {"internal_nodes": true}`), from the mode shapes of `modal` and `buckling` results
//! (their `.vtu` files keep every node), and named as such in error messages.

use super::StaticResult;
use crate::analysis::AnalysisError;
use crate::case::mesh::BuiltHinge;
use crate::fem::Model;

/// Number of inner hinge nodes when they are exactly the model's nodes after the case's
/// `user` nodes (else 0: e.g. a superelement's modal nodes follow, which stay listed).
pub fn trailing_inner(model: &Model, hinges: &[BuiltHinge], user: usize) -> usize {
    let inner: usize = hinges.iter().map(|h| h.inner_nodes.len()).sum();
    if inner > 0 && model.nodes.len() == user + inner {
        inner
    } else {
        0
    }
}

/// Drops the rows of the inner hinge nodes from every load case's `displacements` (one row per
/// node of the case, as the case numbers them) and says so in the model notes.
pub fn hide(r: &mut StaticResult, model: &Model, hinges: &[BuiltHinge], user: usize) {
    let inner = trailing_inner(model, hinges, user);
    if inner == 0 {
        return;
    }
    for c in &mut r.load_cases {
        c.displacements.truncate(user);
    }
    r.model.push(format!(
        "displacements: one row per node of the case; the {inner} inner nodes of segmented hinge elements (nodes {user}–{}) are not listed (\"output\": {{\"internal_nodes\": true}} lists them)",
        user + inner - 1
    ));
}

/// Cuts the per-node rows of mode shapes (`modal`, `buckling`) to the case's `user` nodes when the
/// model's last nodes are inner hinge nodes; the model note saying so, or `None`.
pub fn hide_in_shapes<'a>(
    shapes: impl Iterator<Item = &'a mut Vec<[f64; 6]>>,
    model: &Model,
    hinges: &[BuiltHinge],
    user: usize,
) -> Option<String> {
    let inner = trailing_inner(model, hinges, user);
    if inner == 0 {
        return None;
    }
    for s in shapes {
        s.truncate(user);
    }
    Some(format!(
        "shapes: one row per node of the case; the {inner} inner nodes of segmented hinge elements (nodes {user}–{}) are in the .vtu file only",
        user + inner - 1
    ))
}

/// The message `e` with a line naming the hinge element of the inner nodes it mentions
/// (`node N`), so that a mechanism at node 18 reads as what the user built.
pub fn label(e: AnalysisError, hinges: &[BuiltHinge]) -> AnalysisError {
    // (case element, its inner nodes named), in order of first mention.
    let mut named: Vec<(usize, Vec<usize>)> = Vec::new();
    for (at, _) in e.message.match_indices("node ") {
        let digits: String = e.message[at + 5..].chars().take_while(char::is_ascii_digit).collect();
        let Ok(node) = digits.parse::<usize>() else {
            continue;
        };
        let Some(h) = hinges.iter().find(|h| h.inner_nodes.contains(&node)) else {
            continue;
        };
        match named.iter_mut().find(|(el, _)| *el == h.case_element) {
            Some((_, nodes)) if !nodes.contains(&node) => nodes.push(node),
            Some(_) => {}
            None => named.push((h.case_element, vec![node])),
        }
    }
    if named.is_empty() {
        return e;
    }
    let parts: Vec<String> = named
        .iter()
        .map(|(el, nodes)| {
            let list: Vec<String> = nodes.iter().map(usize::to_string).collect();
            let (word, verb) = if nodes.len() == 1 {
                ("node", "is an inner node")
            } else {
                ("nodes", "are inner nodes")
            };
            format!(
                "{word} {} {verb} of the segmented hinge elements[{el}]",
                list.join(", ")
            )
        })
        .collect();
    AnalysisError::new(e.context, format!("{}\n({})", e.message, parts.join("; ")))
}
