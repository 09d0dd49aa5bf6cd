//! The inner nodes of segmented hinge elements (`"segments"` > 1): numbered after the case's
//! nodes, they are hidden from a `static` result's `displacements` unless the case asks for them
//! (`"output": {"internal_nodes": true}`), and named as such in error messages.

use super::StaticResult;
use crate::analysis::AnalysisError;
use crate::case::mesh::BuiltHinge;
use crate::fem::Model;

/// Number of inner hinge nodes when they are exactly the model's nodes after the case's
/// `user` nodes (else 0: e.g. a superelement's modal nodes follow, which stay listed).
fn trailing_inner(model: &Model, hinges: &[BuiltHinge], user: usize) -> usize {
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

/// The message `e` with a line naming the hinge element of every inner node it mentions
/// (`node N`), so that a mechanism at node 18 reads as what the user built.
pub fn label(e: AnalysisError, hinges: &[BuiltHinge]) -> AnalysisError {
    let mut named: Vec<String> = Vec::new();
    let mut rest = e.message.as_str();
    while let Some(at) = rest.find("node ") {
        rest = &rest[at + 5..];
        let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
        let Ok(node) = digits.parse::<usize>() else {
            continue;
        };
        if let Some(h) = hinges.iter().find(|h| h.inner_nodes.contains(&node)) {
            let text = format!("node {node} is an inner node of the segmented hinge elements[{}]", h.case_element);
            if !named.contains(&text) {
                named.push(text);
            }
        }
    }
    if named.is_empty() {
        return e;
    }
    AnalysisError::new(e.context, format!("{}\n({})", e.message, named.join("; ")))
}
