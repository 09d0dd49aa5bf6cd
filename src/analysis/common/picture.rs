//! `model.svg`: the picture of an FE model, undeformed as a light ghost and deformed (scaled, the
//! scale stated) on top, with hinges drawn as notch symbols coloured by utilisation, rigid bodies
//! shaded, supports and loads as arrows ([`crate::report::model_svg`] draws it).
//!
//! Beams and hinge segments are drawn straight between their (displaced) end nodes: a hinge
//! split into co-rotational segments bends through its inner nodes, a single beam element does
//! not.

use super::vtu::Drawn;
use crate::case::mesh::{PictureRequest, ViewRequest};
use crate::fem::{Element, LoadCase, Model};
use crate::report::model_svg::{self, Arrow, Item, Mark, Picture, Shape, View};

/// A notch symbol to draw: a hinge from node `nodes[0]` to `nodes[1]` of the model.
#[derive(Debug, Clone, PartialEq)]
pub struct HingeMark {
    /// What the result calls it (e.g. `element 3`).
    pub label: String,
    /// Its end nodes.
    pub nodes: [usize; 2],
    /// Peak stress over allowable (−); `None` without an allowable.
    pub utilisation: Option<f64>,
}

/// What one picture shows.
pub struct Scene<'a> {
    /// The model.
    pub model: &'a Model,
    /// Nodal [ux, uy, uz, rx, ry, rz] (mm, rad) of the deformed state (a load case or a mode
    /// shape); `None`: the undeformed model only.
    pub displacements: Option<&'a [[f64; 6]]>,
    /// Hinges to mark.
    pub marks: Vec<HingeMark>,
    /// Rigid bodies drawn beside the elements.
    pub drawn: &'a Drawn,
    /// The load case whose loads are drawn as arrows.
    pub load_case: Option<&'a LoadCase>,
    /// The title line.
    pub title: String,
    /// The load case or mode shown (its name, or `mode 1`), echoed as `data-load-case`.
    pub name: String,
    /// What is deformed, for the caption (`load case "x"`, `mode 1, 12.3 Hz`).
    pub what: String,
    /// A mode shape (arbitrary amplitude): the caption states the drawn size, not a scale.
    pub mode: bool,
}

/// The automatic deformation scale: 1 when the largest displacement `u_max` is at least 5 % of
/// the model's size, else the round number (1, 2, 5 × 10ⁿ, rounded down) that draws it as
/// about 8 % of the size.
pub fn auto_scale(u_max: f64, size: f64) -> f64 {
    if !(u_max > 0.0 && size > 0.0) || u_max >= 0.05 * size {
        return 1.0;
    }
    let target = 0.08 * size / u_max;
    let decade = 10f64.powf(target.log10().floor());
    let m = target / decade;
    let step = if m >= 5.0 {
        5.0
    } else if m >= 2.0 {
        2.0
    } else {
        1.0
    };
    step * decade
}

/// Renders `scene` with the options of `req` (view, scale, numbers).
pub fn render(scene: &Scene, req: &PictureRequest) -> String {
    let model = scene.model;
    let mut points = model.nodes.clone();
    let mut items = Vec::new();
    for e in &model.elements {
        match e {
            Element::Beam(b) => items.push(Item {
                shape: Shape::Beam {
                    width: b.section.properties(b.material.nu).a.max(0.0).sqrt(),
                },
                points: b.nodes.to_vec(),
            }),
            Element::Flex(f) => items.push(Item {
                shape: Shape::HingeLine,
                points: f.nodes.to_vec(),
            }),
            Element::Spring(s) => {
                if let Some(b) = s.b {
                    items.push(Item {
                        shape: Shape::Spring,
                        points: vec![s.a, b],
                    });
                }
            }
            Element::Matrix(_) => {}
            Element::Shell4(s) => {
                let n = s.nodes;
                let pts = if n[3] == n[2] {
                    vec![n[0], n[1], n[2]]
                } else {
                    n.to_vec()
                };
                items.push(Item {
                    shape: Shape::Shell { utilisation: None },
                    points: pts,
                });
            }
            // The outline through the edge midpoints.
            Element::Shell9(s) => {
                let n = s.nodes;
                items.push(Item {
                    shape: Shape::Shell { utilisation: None },
                    points: vec![n[0], n[4], n[1], n[5], n[2], n[6], n[3], n[7]],
                });
            }
        }
    }
    for r in &model.rigid_links {
        let mut pts = vec![r.master];
        pts.extend(&r.slaves);
        items.push(Item {
            shape: Shape::Rigid,
            points: pts,
        });
    }
    for c in &scene.drawn.cells {
        items.push(Item {
            shape: Shape::Body,
            points: c.points().to_vec(),
        });
    }
    let mut owner: Vec<usize> = (0..model.nodes.len()).collect();
    for b in &scene.drawn.lines {
        points.push(b.point);
        owner.push(b.node);
        items.push(Item {
            shape: Shape::Body,
            points: vec![b.node, points.len() - 1],
        });
    }

    let size = crate::fem::model::model_size(&model.nodes);
    let u_max = scene.displacements.map_or(0.0, |u| {
        u.iter()
            .take(model.nodes.len())
            .map(|d| (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt())
            .fold(0.0, f64::max)
    });
    let scale = req.scale.unwrap_or_else(|| {
        if scene.mode && u_max > 0.0 && size > 0.0 {
            // A mode's amplitude is arbitrary: draw its largest displacement as 8 % of the size.
            0.08 * size / u_max
        } else {
            auto_scale(u_max, size)
        }
    });
    let deformed: Option<Vec<[f64; 3]>> = scene.displacements.filter(|_| u_max > 0.0).map(|u| {
        points
            .iter()
            .zip(&owner) // zip-checked: `owner` has one entry per point, pushed together above
            .map(|(p, &n)| {
                let d = u.get(n).copied().unwrap_or([0.0; 6]);
                [p[0] + scale * d[0], p[1] + scale * d[1], p[2] + scale * d[2]]
            })
            .collect()
    });
    let caption = match (&deformed, scene.mode) {
        (None, _) => format!("{}: undeformed (no displacement)", scene.what),
        (Some(_), true) => format!(
            "{}: shape drawn with its largest displacement {} % of the model size; undeformed in grey",
            scene.what,
            crate::report::markdown::sig(100.0 * scale * u_max / size.max(1e-300), 3)
        ),
        (Some(_), false) => format!(
            "{}: deformation × {} (largest displacement {} mm); undeformed in grey",
            scene.what,
            scale,
            crate::report::markdown::sig(u_max, 4)
        ),
    };

    let supports: Vec<usize> = model
        .supports
        .iter()
        .filter(|s| s.fix.iter().any(|&f| f))
        .map(|s| s.node)
        .collect();
    let mut arrows = Vec::new();
    if let Some(lc) = scene.load_case {
        for f in &lc.forces {
            if f.f[..3].iter().any(|v| *v != 0.0) {
                arrows.push(Arrow {
                    point: f.node,
                    direction: [f.f[0], f.f[1], f.f[2]],
                    prescribed: false,
                });
            }
        }
        for p in &lc.displacements {
            let k = p.dof as usize;
            if k < 3 && p.value != 0.0 {
                let axis = model.frames.get(&p.node).map_or_else(
                    || {
                        let mut a = [0.0; 3];
                        a[k] = 1.0;
                        a
                    },
                    |f| f[k],
                );
                let s = p.value.signum();
                arrows.push(Arrow {
                    point: p.node,
                    direction: [s * axis[0], s * axis[1], s * axis[2]],
                    prescribed: true,
                });
            }
        }
    }
    let marks: Vec<Mark> = scene
        .marks
        .iter()
        .map(|m| Mark {
            label: m.label.clone(),
            points: m.nodes,
            utilisation: m.utilisation,
        })
        .collect();
    let view = req.view.map(|v: ViewRequest| {
        let (azimuth_deg, elevation_deg) = v.angles();
        View {
            azimuth_deg,
            elevation_deg,
        }
    });
    model_svg::render(&Picture {
        points: &points,
        deformed: deformed.as_deref(),
        scale,
        items: &items,
        marks: &marks,
        supports: &supports,
        arrows: &arrows,
        title: &scene.title,
        caption: &caption,
        load_case: &scene.name,
        view,
        numbers: req.numbers,
    })
}

#[cfg(test)]
mod tests {
    use super::auto_scale;

    #[test]
    fn automatic_scale_is_round_and_draws_about_eight_percent() {
        // 0.01 mm on a 100 mm model: 8 / 0.01 = 800 → 500 (1-2-5, rounded down).
        assert_eq!(auto_scale(0.01, 100.0), 500.0);
        assert_eq!(auto_scale(0.004, 100.0), 2000.0);
        // Large displacements are drawn true to scale.
        assert_eq!(auto_scale(6.0, 100.0), 1.0);
        assert_eq!(auto_scale(0.0, 100.0), 1.0);
    }
}
