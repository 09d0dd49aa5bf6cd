//! Builds the FE model from the model shapes ([`super::shapes`]): validates every reference and
//! value once, naming its JSON path.

use super::frames;
use super::hinge::BuiltHinge;
use super::lookup::{BuiltSection, Ctx, Named};
use super::shapes::{ElementSpec, MeshSpec, RigidSpec, SectionSpec};
use crate::case::error::{check, CaseError};
use crate::fem::{self, Dof};
use std::collections::BTreeMap;

impl MeshSpec {
    /// Combines a mesh file's model with inline additions: inline materials and sections are
    /// added (inline wins on equal names), inline load cases replace the mesh's.
    pub fn merge_inline(mut mesh: MeshSpec, inline: MeshSpec) -> Result<MeshSpec, CaseError> {
        for (field, given) in [
            ("nodes", !inline.nodes.is_empty()),
            ("elements", !inline.elements.is_empty()),
            ("supports", !inline.supports.is_empty()),
            ("rigid_links", !inline.rigid_links.is_empty()),
        ] {
            if given {
                return Err(CaseError::new(
                    field,
                    "the model comes from `mesh`: give nodes, elements, supports and rigid links there, not inline",
                ));
            }
        }
        mesh.materials.extend(inline.materials);
        mesh.sections.extend(inline.sections);
        if !inline.load_cases.is_empty() {
            mesh.load_cases = inline.load_cases;
        }
        if inline.ordering.is_some() {
            mesh.ordering = inline.ordering;
        }
        if inline.shell_elements.is_some() {
            mesh.shell_elements = inline.shell_elements;
        }
        Ok(mesh)
    }

    /// Validates every reference and value and builds the FE model (at least one load case).
    pub fn build(&self) -> Result<fem::Model, CaseError> {
        self.build_model(true)
    }

    /// As [`MeshSpec::build`]; `need_loads = false` accepts a model without load cases (modal).
    pub fn build_model(&self, need_loads: bool) -> Result<fem::Model, CaseError> {
        self.build_with_hinges(need_loads, false).map(|(m, _)| m)
    }

    /// As [`MeshSpec::build_model`], also returning the model's hinge elements (their element
    /// index, hinge region and allowable stress) for the per-hinge results. `nonlinear`: the
    /// model is for a geometrically nonlinear run (hinge elements without `segments` are then
    /// split into [`crate::hinge::NONLINEAR_SEGMENTS`]).
    pub fn build_with_hinges(
        &self,
        need_loads: bool,
        nonlinear: bool,
    ) -> Result<(fem::Model, Vec<BuiltHinge>), CaseError> {
        self.build_indexed(need_loads, nonlinear).map(|(m, h, _)| (m, h))
    }

    /// As [`MeshSpec::build_with_hinges`], also returning the model element index of each case
    /// element (`None` for rigid links and point masses).
    #[allow(clippy::type_complexity)]
    pub fn build_indexed(
        &self,
        need_loads: bool,
        nonlinear: bool,
    ) -> Result<(fem::Model, Vec<BuiltHinge>, Vec<Option<usize>>), CaseError> {
        let materials = Named::validate("material", "materials", &self.materials, |m, p| m.resolve(p))?;
        let sections = Named::validate("section", "sections", &self.sections, section)?;
        if self.nodes.is_empty() {
            return Err(CaseError::new("nodes", "the model has no nodes"));
        }
        let mut cx = Ctx {
            spec: self,
            materials,
            sections,
            model: fem::Model::new(),
            frame_owner: BTreeMap::new(),
            model_index: Vec::with_capacity(self.elements.len()),
            hinges: Vec::new(),
            nonlinear,
            tie_paths: Vec::new(),
            regions: Vec::new(),
            specs: Vec::new(),
        };
        for (i, x) in self.nodes.iter().enumerate() {
            for (k, v) in x.iter().enumerate() {
                check::finite(format_args!("nodes[{i}][{k}]"), *v)?;
            }
            cx.model.add_node(*x);
        }
        // Nodes added by "shell_elements": "shell9" follow their parents (a sweep moves corners).
        if let Some(p) = &self.promoted {
            p.place(&mut cx.model.nodes);
        }
        let size = super::joint::model_size(&self.nodes);
        let mut rigid: Vec<(String, RigidSpec)> = self
            .rigid_links
            .iter()
            .enumerate()
            .map(|(i, r)| (format!("rigid_links[{i}]"), r.clone()))
            .collect();
        for (ie, e) in self.elements.iter().enumerate() {
            let p = format!("elements[{ie}]");
            let before = cx.model.elements.len();
            if let ElementSpec::Rigid { master, slaves } = e {
                rigid.push((
                    p,
                    RigidSpec {
                        master: *master,
                        slaves: slaves.clone(),
                    },
                ));
            } else {
                super::conflicts::element_length(&cx, &p, e, size)?;
                element(&mut cx, &p, e)?;
            }
            let built = (cx.model.elements.len() > before).then_some(before);
            cx.model_index.push(built);
        }
        if nonlinear {
            let hinges = &cx.hinges;
            super::corot_length::check(self, |i| {
                hinges.iter().find(|h| h.case_element == i).map(|h| h.segments)
            })?;
        }
        // Hinges of several segments: inner nodes and further elements after the case's own,
        // so node and element indices of the case stay those of the model.
        // Then every hinge's mass on its chain of nodes.
        // Identical hinges (one region, material and segment count: a `hinge_types` entry at
        // equal node distances) share their chain's compliances, integrated once.
        let mut chains: Vec<(usize, Vec<[[f64; 6]; 6]>)> = Vec::new();
        for k in 0..cx.hinges.len() {
            let first_inner = cx.model.nodes.len();
            let element = cx.hinges[k].element;
            if cx.hinges[k].segments > 1 {
                let h = &cx.hinges[k];
                let same = |j: usize| {
                    let g = &cx.hinges[j];
                    g.region == h.region && g.material == h.material && g.segments == h.segments
                };
                let at = match chains.iter().position(|&(j, _)| same(j)) {
                    Some(at) => at,
                    None => {
                        let cs = super::hinge_memo::chain(&h.region, &h.material, h.segments);
                        chains.push((k, cs));
                        chains.len() - 1
                    }
                };
                if let Some(last) = crate::hinge::split_flex_with(&mut cx.model, element, &chains[at].1) {
                    cx.hinges[k].last = last;
                }
            }
            let h = &mut cx.hinges[k];
            let ends = |ie: usize| match cx.model.elements.get(ie) {
                Some(fem::Element::Flex(f)) => Some(f.nodes),
                _ => None,
            };
            h.inner_nodes = first_inner..cx.model.nodes.len();
            if let (Some([a, _]), Some([_, b])) = (ends(h.element), ends(h.last)) {
                let chain: Vec<usize> = std::iter::once(a)
                    .chain(first_inner..cx.model.nodes.len())
                    .chain(std::iter::once(b))
                    .collect();
                super::hinge::chain_masses(&mut cx.model, &chain, &h.region, h.material.density);
            }
        }
        let rigid_paths: Vec<String> = rigid.iter().map(|(p, _)| p.clone()).collect();
        for (p, r) in rigid {
            let master = cx.node(format!("{p}.master"), r.master)?;
            let mut slaves = Vec::with_capacity(r.slaves.len());
            for (i, s) in r.slaves.iter().enumerate() {
                let s = cx.node(format!("{p}.slaves[{i}]"), *s)?;
                if cx.model.frames.contains_key(&s) {
                    return Err(CaseError::value(
                        format!("{p}.slaves[{i}]"),
                        s,
                        "this node carries the frame of a joint element and a rigid-link slave cannot: make it the link's master, or join it by a stiff beam",
                    ));
                }
                slaves.push(s);
            }
            cx.model.rigid_links.push(fem::RigidLink { master, slaves });
        }
        let first_support = cx.model.supports.len();
        for (i, s) in self.supports.iter().enumerate() {
            let node = cx.node(format!("supports[{i}].node"), s.node)?;
            let dofs: Vec<Dof> = s.fix.iter().map(|d| d.dof()).collect();
            let p = format!("supports[{i}]");
            match frames::local(&p, s.frame, s.axis)? {
                Some(l) => {
                    if l.axis_only {
                        frames::check_axis_dofs(&format!("{p}.fix"), &s.fix)?;
                    }
                    frames::set_node_frame(
                        &mut cx,
                        &format!("{p}.{}", if l.axis_only { "axis" } else { "frame" }),
                        node,
                        l.rows,
                    )?;
                }
                None if cx.model.frames.contains_key(&node) && dofs.len() < 6 => {
                    let owner = cx.frame_owner.get(&node).cloned().unwrap_or_default();
                    return Err(CaseError::value(
                        format!("{p}.fix"),
                        format!("{:?}", s.fix),
                        format!("node {node} carries the frame of `{owner}`, in which a partial support would act: give the support that `frame`, clamp all six DOFs, or support a node joined to it"),
                    ));
                }
                None => {}
            }
            cx.model.supports.push(fem::Support::dofs(node, &dofs));
        }
        // A tie makes node b follow node a, so b must carry no support: a joint whose second
        // node is supported ties the other way round (the joint is symmetric).
        for t in &mut cx.model.ties {
            let supported = |n: usize| cx.model.supports.iter().any(|s| s.node == n);
            if supported(t.b) && !supported(t.a) {
                std::mem::swap(&mut t.a, &mut t.b);
            }
        }
        if need_loads && self.load_cases.is_empty() {
            return Err(CaseError::new("load_cases", "at least one load case is needed"));
        }
        unique_load_case_names(self.load_cases.iter().map(|c| c.name.as_str()))?;
        for (ic, c) in self.load_cases.iter().enumerate() {
            let lc = super::build_loads::load_case(&mut cx, &format!("load_cases[{ic}]"), c)?;
            if need_loads && lc.forces.is_empty() && lc.displacements.is_empty() {
                return Err(CaseError::value(
                    format!("load_cases[{ic}]"),
                    format!("\"{}\"", c.name),
                    "the load case loads nothing: give `forces`, `displacements`, `pressures`, `edge_loads`, `line_loads`, `group_forces` or a non-zero `gravity`",
                ));
            }
            cx.model.load_cases.push(lc);
        }
        super::conflicts::constraint_conflicts(&cx.model, &rigid_paths, &cx.tie_paths, first_support)?;
        cx.model.ordering = self.ordering.map(|o| o.fill_ordering()).unwrap_or_default();
        Ok((cx.model, cx.hinges, cx.model_index))
    }
}

/// Builds one case element (not a rigid link) into the model.
fn element(cx: &mut Ctx, p: &str, e: &ElementSpec) -> Result<(), CaseError> {
    match e {
        ElementSpec::Beam {
            nodes,
            section,
            material,
            up,
            shear,
        } => {
            let (a, b) = cx.two_nodes(p, *nodes, "beam")?;
            let BuiltSection::Beam(sec) = *cx.sections.get(&format!("{p}.section"), section)? else {
                return Err(wrong_section(p, section, "a shell section cannot be used by a beam"));
            };
            let mat = *cx.materials.get(&format!("{p}.material"), material)?;
            cx.axis_and_up(p, (a, b), *up, "beam")?;
            let mut beam = fem::Beam::new(a, b, sec, mat, *up);
            if !shear {
                beam = beam.euler_bernoulli();
            }
            cx.model.add_beam(beam);
        }
        ElementSpec::Spring { nodes, k } => {
            if nodes.is_empty() || nodes.len() > 2 {
                return Err(CaseError::value(
                    format!("{p}.nodes"),
                    format!("{nodes:?}"),
                    "a spring has one node (to ground) or two",
                ));
            }
            for (i, kv) in k.iter().enumerate() {
                check::non_negative(format_args!("{p}.k[{i}]"), *kv, "N/mm or N·mm/rad")?;
            }
            let a = cx.node(format!("{p}.nodes[0]"), nodes[0])?;
            let b = match nodes.get(1) {
                Some(&b) => Some(cx.node(format!("{p}.nodes[1]"), b)?),
                None => None,
            };
            cx.model.add_element(fem::Element::Spring(fem::Spring {
                a,
                b,
                k: *k,
                axes: fem::SpringAxes::Global,
            }));
        }
        ElementSpec::Mass { node, mass, inertia } => {
            let node = cx.node(format!("{p}.node"), *node)?;
            check::non_negative(format_args!("{p}.mass"), *mass, "tonne")?;
            for (i, v) in inertia.iter().enumerate() {
                check::non_negative(format_args!("{p}.inertia[{i}]"), *v, "tonne·mm²")?;
            }
            cx.model.masses.push(fem::PointMass {
                node,
                mass: *mass,
                inertia: *inertia,
            });
        }
        ElementSpec::Rigid { .. } => {}
        ElementSpec::Hinge {
            nodes,
            hinge,
            material,
            up,
            segments,
        } => {
            super::hinge::hinge_element(cx, p, *nodes, hinge, material, *up, cx.model_index.len())?;
            if let Some(n) = segments {
                super::hinge::set_segments(cx, p, *n)?;
            }
        }
        ElementSpec::Joint {
            nodes,
            kind,
            axis,
            axis2,
            frame,
        } => super::joint::joint_element(cx, p, *nodes, *kind, [*axis, *axis2], *frame)?,
        ElementSpec::Shell4 {
            nodes,
            section,
            material,
        } => shell4(cx, p, *nodes, section, material)?,
        ElementSpec::Shell9 {
            nodes,
            section,
            material,
        } => shell9(cx, p, *nodes, section, material)?,
        ElementSpec::Superelement {
            file,
            nodes,
            placement,
            loaded,
        } => super::superelement::superelement_element(cx, p, file, nodes, placement.as_ref(), loaded.as_ref())?,
    }
    Ok(())
}

fn shell4(cx: &mut Ctx, p: &str, nodes: [usize; 4], section: &str, material: &str) -> Result<(), CaseError> {
    let mut ns = [0usize; 4];
    for (k, &nd) in nodes.iter().enumerate() {
        ns[k] = cx.node(format!("{p}.nodes[{k}]"), nd)?;
    }
    // A triangle may be given as a degenerate quad [a, b, c, c].
    for a in 0..4 {
        for b in 0..a {
            if ns[a] == ns[b] && !(a == 3 && b == 2) {
                return Err(CaseError::value(
                    format!("{p}.nodes"),
                    format!("{ns:?}"),
                    "a shell4 needs four different nodes (or [a, b, c, c] for a triangle)",
                ));
            }
        }
    }
    let BuiltSection::Shell(t) = *cx.sections.get(&format!("{p}.section"), section)? else {
        return Err(wrong_section(
            p,
            section,
            "a shell4 needs a section with \"shape\": \"shell\"",
        ));
    };
    let mat = *cx.materials.get(&format!("{p}.material"), material)?;
    let x = ns.map(|i| cx.spec.nodes[i]);
    if fem::shell::shell_geometry(&x).is_none() {
        return Err(CaseError::value(
            format!("{p}.nodes"),
            format!("{ns:?}"),
            "the four nodes must form a convex quadrilateral, listed around it (not crossed, no zero area)",
        ));
    }
    cx.model.add_element(fem::Element::Shell4(fem::Shell4 {
        nodes: ns,
        t,
        material: mat,
    }));
    Ok(())
}

fn shell9(cx: &mut Ctx, p: &str, nodes: [usize; 9], section: &str, material: &str) -> Result<(), CaseError> {
    let mut ns = [0usize; 9];
    for (k, &nd) in nodes.iter().enumerate() {
        ns[k] = cx.node(format!("{p}.nodes[{k}]"), nd)?;
    }
    for a in 0..9 {
        for b in 0..a {
            if ns[a] == ns[b] {
                return Err(CaseError::value(
                    format!("{p}.nodes"),
                    format!("{ns:?}"),
                    "a shell9 needs nine different nodes",
                ));
            }
        }
    }
    let BuiltSection::Shell(t) = *cx.sections.get(&format!("{p}.section"), section)? else {
        return Err(wrong_section(
            p,
            section,
            "a shell9 needs a section with \"shape\": \"shell\"",
        ));
    };
    let mat = *cx.materials.get(&format!("{p}.material"), material)?;
    let x = ns.map(|i| cx.spec.nodes[i]);
    if let Err(e) = fem::shell9::shell9_geometry(&x) {
        return Err(CaseError::value(format!("{p}.nodes"), format!("{ns:?}"), e.to_string()));
    }
    cx.model.add_element(fem::Element::Shell9(fem::Shell9 {
        nodes: ns,
        t,
        material: mat,
    }));
    Ok(())
}

/// The longest load case name, characters: its output files (`NAME.vtu`, `NAME_….csv`) stay
/// under the 255-byte file-name limit of common file systems.
pub const MAX_LOAD_CASE_NAME: usize = 200;

/// Refuses a load case name longer than [`MAX_LOAD_CASE_NAME`], two load cases with the same name, or with names that give the same output file
/// name (each load case writes `NAME.vtu`): the error names `load_cases[i].name` of the later.
pub fn unique_load_case_names<'a>(names: impl Iterator<Item = &'a str> + Clone) -> Result<(), CaseError> {
    // Pairwise (a case has few load cases): no allocation unless two names clash.
    for (i, name) in names.clone().enumerate() {
        let chars = name.chars().count();
        if chars > MAX_LOAD_CASE_NAME {
            return Err(CaseError::value(
                format!("load_cases[{i}].name"),
                format!("\"{}…\" ({chars} characters)", name.chars().take(24).collect::<String>()),
                format!("a load case name is at most {MAX_LOAD_CASE_NAME} characters (it names the load case's output files, and file systems allow 255 bytes)"),
            ));
        }
        let Some((j, first)) = names
            .clone()
            .take(i)
            .enumerate()
            .find(|(_, b)| crate::report::vtk::same_file_stem(name, b))
        else {
            continue;
        };
        let why = if first == name {
            format!("load_cases[{j}] has the same name; load case names must be unique")
        } else {
            let stem = crate::report::vtk::file_stem(name);
            format!(
                "load_cases[{j}] (\"{first}\") gives the same output file name `{stem}.vtu`; load case names must differ in letters, digits, `-` or `_`"
            )
        };
        return Err(CaseError::value(
            format!("load_cases[{i}].name"),
            format!("\"{name}\""),
            why,
        ));
    }
    Ok(())
}
/// Validates a section.
fn section(s: &SectionSpec, p: &str) -> Result<BuiltSection, CaseError> {
    let f = |k: &str| format!("{p}.{k}");
    Ok(BuiltSection::Beam(match *s {
        SectionSpec::Rect { w, h } => {
            check::positive(f("w"), w, "mm")?;
            check::positive(f("h"), h, "mm")?;
            fem::Section::Rect { w, h }
        }
        SectionSpec::Circle { d } => {
            check::positive(f("d"), d, "mm")?;
            fem::Section::Circle { d }
        }
        SectionSpec::Tube { d, t } => {
            check::positive(f("d"), d, "mm")?;
            check::positive(f("t"), t, "mm")?;
            if 2.0 * t >= d {
                return Err(CaseError::value(
                    f("t"),
                    t,
                    format!("the wall must be thinner than half the diameter ({} mm)", d / 2.0),
                ));
            }
            fem::Section::Tube {
                d_out: d,
                d_in: d - 2.0 * t,
            }
        }
        SectionSpec::General { a, iy, iz, j, asy, asz } => {
            check::positive(f("A"), a, "mm²")?;
            check::positive(f("Iy"), iy, "mm⁴")?;
            check::positive(f("Iz"), iz, "mm⁴")?;
            check::positive(f("J"), j, "mm⁴")?;
            if let Some(v) = asy {
                check::positive(f("Asy"), v, "mm²")?;
            }
            if let Some(v) = asz {
                check::positive(f("Asz"), v, "mm²")?;
            }
            fem::Section::General { a, iy, iz, j, asy, asz }
        }
        SectionSpec::Shell { t } => {
            check::positive(f("t"), t, "mm")?;
            return Ok(BuiltSection::Shell(t));
        }
    }))
}

/// The error of element `p` naming a section of the wrong kind.
fn wrong_section(p: &str, section: &str, allowed: &str) -> CaseError {
    CaseError::value(format!("{p}.section"), format!("\"{section}\""), allowed)
}
