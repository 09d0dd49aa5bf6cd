//! Hinge models against a second, independent solid solver: CalculiX.
//!
//! The references below were computed with `tools/ccx_reference.py`: the geometry and
//! 10-node-tetrahedron mesh of `tools/solid_reference.py` (gmsh 4.15, OpenCASCADE; element size
//! the local thickness / 4, at most h/3), solved by CalculiX ccx 2.20 (Debian's `calculix-ccx`,
//! SPOOLES) with C3D10 elements; one blank end face clamped, the other made rigid by
//! *RIGID BODY (kinematic: every face node follows the rigid motion, the boundary condition of
//! the `hinge` analysis), unit loads at the face centre (an axial force, three moments) giving
//! the diagonal compliances; peak von Mises stress under the unit compliant-axis moment both at
//! the integration points and nodal-averaged. Raw results: `tools/ccx_reference_results.jsonl`.
//!
//! Mesh convergence. Every model was solved at n = 4 elements across the local thickness, and
//! at n = 3 too (`tools/ccx_refine.py`, `tools/ccx_refine_n3_results.jsonl`): **the stiffnesses
//! compared are the order-2 Richardson extrapolation of the pair** ([`CcxRef::converged`]).
//! n = 4 alone is up to 5.8 % too stiff in bending, 8.9 % in torsion and 3.1 % in axial (22 % in
//! bending and torsion on the sixteenth design's blanks 10–14 t tall, where n = 3 is too coarse
//! and the references take the n = 4/6 extrapolation); the clamped
//! face's edges are singular, so the stiffnesses converge as h² (measured order 1.85–2.5), not
//! as the h⁴ of smooth P2 problems that an earlier version of this file assumed from two hinges.
//! The extrapolation agrees with the n = 4/6 one on the references re-solved at n = 6, and with
//! n = 6/8 on the hinge that showed it ([`extrapolation_checked_on_finer_meshes`]).
//! The peak stresses are not those of these meshes: at a small fillet the radius, not the
//! thickness, sets the stress gradient, and n = 4 reads the peak up to 9.3 % low (l4.5/R0.75/t1.5,
//! R/t 0.5). Each circular and corner-filleted reference was solved again for its peak alone on
//! its symmetric eighth with the mesh sized by the notch radius (`tools/ccx_peak_stress.py`,
//! [`converged_peaks_checked`]), and those converged peaks are the ones compared; the turned
//! necks keep their n = 4 peak (the four necks' peaks move by less than [`NECK_PEAK_N4_TO_N6`]
//! from n = 4 to 6, [`converged_peaks_checked`]). Earlier, with the peaks compared at
//! n = 4 (from n = 3 to 4 the peak node can
//! change, so the pair does not extrapolate), the nodal-averaged peak converges faster than the
//! integration-point one: n = 3 → 4 → 5 moves the nodal peak +1.35 %, then +0.39 % on the Ruiz
//! et al. notch R8/t2 (+2.1 %, then +0.63 % on the corner-filleted l6/R2/t1.5 hinge), the
//! integration-point peak +2.69 %, then +2.29 % (+3.8 %, then +1.24 %), rows of
//! `tools/ccx_reference_convergence.jsonl`. The integration-point peak stays below the nodal one
//! at every mesh (4.9–6.8 % at n = 5: its points lie inside the elements, the peak on the
//! surface): the nodal-averaged peak is the converged stress definition and the one compared
//! here ([`peak_stress_mesh_convergence`]); n = 4 → 6 moves it by the band of
//! [`PEAK_N4_TO_N6`] on the re-solved references (the l5.95/R1.45 hinge: +3.6 % from n = 4 to 6,
//! +4.7 % to 8).
//!
//! The first calibration's split (the cases used to fit kept apart from those used to check;
//! superseded for torsion, see below): of the 35 circular and
//! corner-filleted rows computed before the torsion corrections
//! (`hinge::torsion::solid_torsion_stiffness`) and the corner-filleted K_t exponent
//! (`hinge::stress::stress_concentration`) were fitted, every other one in the order of w/t,
//! then t/R, per family, is a FIT row (11 circular, 7 corner-filleted); the Ruiz et al. notch
//! and neck, geometries of the earlier scikit-fem fits, are FIT rows too. The torsion
//! corrections were fitted on these rows together with the fitted rows of the scikit-fem
//! models (tests/hinge_solid_reference.rs), the corner-filleted K_t on the corner-filleted FIT
//! rows alone. Every other row is
//! HELD_OUT, among them all the rows computed after the fit (5 circular notches, 6
//! corner-filleted hinges).
//!
//! The current torsion law and its check (the torsion of `hinge::torsion::solid_torsion_stiffness`).
//! Once all 50 rows above had been looked at, a first fresh design of experiments ([`DOE1`],
//! 24 rows) was drawn by a written rule (`tools/ccx_heldout_doe.py`: a Latin hypercube, numpy
//! `default_rng(20261128)`, log-uniform over t/R 0.08–0.5 and w/t 0.5–20 for circular notches,
//! R/t 0.5–2.5, flat (l − 2R)/t 0.3–6 and w/t 1–20 for corner-filleted hinges, 8 rows each, plus
//! 4 rows per family in the regimes the model missed; blank height t + R or 2t + 2R, blank
//! length = h) and committed (`tools/ccx_heldout_doe.json`) before its solid models were run
//! (`tools/ccx_heldout_results.jsonl`). Refits of the first law on the 50 rows were tried and
//! none lowered the worst torsion error of both families together, so the first law was
//! compared with [`DOE1`] unchanged, once: wide hinges between wide, low blanks (blank
//! w/h ≥ 2.9, w/t 10–17) came out 19–22 % too stiff in torsion in both families (the 50 rows
//! had w/t ≤ 10 and blanks tied to t and R). A second design ([`DOE2`], 24 rows, the same rule
//! with `default_rng(20261129)` and the blank's height and length varied independently, plus
//! wide, low blanks; `tools/ccx_heldout2_doe.json`) was then committed, its models run, and
//! the torsion law refitted on all 74 earlier rows (Benscoter's warping shear added, the
//! plate-mode centre and the spreading slope refitted) and committed before [`DOE2`] was
//! compared, once.
//!
//! The corner-filleted bending law and its check. [`DOE2`] left corner-filleted bending too
//! stiff on large fillets (up to +4.45 % held out, +4.84 % on the fit rows). The short-notch
//! factor G of `hinge::solid_effects` (ρ = R) applied to the whole corner-filleted profile
//! over-corrected every corner row (−7 … −1 %): the missing compliance is in the fillets, where
//! the thickness changes, not in the flat. So G (ρ = R, no number refitted) now divides the
//! compliant-axis modulus on the two fillet arcs only, which took the 44 corner rows then known
//! to −3.60 … +0.13 %. Before that change, with all 98 rows seen, a third design ([`DOE3`],
//! `tools/ccx_heldout_doe.py --third`: numpy `default_rng(20261130)`, 8 corner rows over the
//! calibrated range, 8 over large fillets R/t 1.2–2.5 with short flats, 4 circular notches;
//! `tools/ccx_heldout3_doe.json`) was committed, its models run while the law was written, and
//! the law frozen and committed before [`DOE3`] was compared, once.
//!
//! The references' convergence and the torsion law's warping spreading. Every reference was then
//! re-solved at n = 3 (see the mesh convergence above) and the stiffnesses compared became the
//! extrapolation, decided and committed before any comparison (later, where a reference was
//! also re-solved at n = 6, the n = 4/6 extrapolation: [`converged_stiffness`]). A fourth
//! design ([`DOE4`], `--fourth`: `default_rng(20261201)`, 12 circular, 12 corner-filleted rows)
//! was committed before its models were run and compared once with the model as it stood: circular notches
//! met every target; corner-filleted torsion read up to +12.4 % (wide leaves between low
//! blanks) and one axial −5.6 %. A fifth design ([`DOE5`], `--fifth`, `default_rng(20261202)`)
//! was committed before the torsion law's warping constant was given the bending's load
//! spreading (no new number), that change committed before [`DOE5`]'s models were compared,
//! once. So the FIT rows are the 98 earlier ones (the 50 of the first calibration, `FIRST_FIT`
//! and `FIRST_HELD_OUT` named by that split, [`DOE1`] and [`DOE2`]); [`DOE3`] and [`DOE4`] are
//! held out from the bending, axial and stress laws and were seen by the last torsion change;
//! [`DOE5`] is held out from every law. The corner-filleted K_t exponent, first fitted on
//! `FIRST_FIT` against n = 4 peaks, was refitted (one number, the minimax over the 44
//! corner-filleted FIT rows) against the converged peaks once those were computed, after every
//! design above had been solved: [`DOE3`], [`DOE4`] and [`DOE5`] are held out of that refit.
//! The circular notches' peak stress is not fitted on these models.
//!
//! The axial law and the sixth design. A sixth design ([`DOE6`], `--sixth`,
//! `default_rng(20261203)`, 12 circular and 12 corner-filleted rows) was committed before its
//! models were run and before the axial modulus of the notch region took the short-notch G and
//! a share of the plane-strain restraint, E·(1 + 0.6(P − 1))/G (`hinge::solid_effects`: the share
//! the minimax fit on the 94 circular and corner-filleted FIT rows; [`DOE3`] to [`DOE5`] were
//! not used); that law was committed before [`DOE3`] to [`DOE5`] were compared with it and
//! before [`DOE6`] was solved, and [`DOE6`] was then compared once.
//!
//! The warping spread slope and the seventh design. [`DOE6`] held a second short wide
//! corner-filleted leaf too soft in torsion (−13.3 %). A seventh design ([`DOE7`], `--seventh`,
//! `default_rng(20261204)`: 12 circular and 12 corner-filleted rows by the fourth set's rule,
//! then 8 short wide corner-filleted leaves drawn from the region of both misses) was committed
//! before the torsion law's warping constant was given its own spread slope, 0.57
//! (`hinge::torsion::solid`: one number, the minimax of the torsion error over all 186
//! circular and corner-filleted rows of [`DOE1`] to [`DOE6`] and the first calibration); that
//! law was committed before [`DOE7`] was solved, and [`DOE7`] was then compared once. So
//! [`DOE7`] is held out from every law, and [`DOE3`] to [`DOE6`] from every fit but the
//! warping slope's, and seen by later changes. The comparison found the shortest, widest leaf
//! with sharp fillets still too soft; re-solving the short or wide leaves at n = 6 then showed
//! their n = 3/4 extrapolations over-correcting (by up to 3.7 %, on the two leaves with R/t
//! 0.52), so the tables now take the n = 4/6 extrapolation wherever it exists, a decision on the
//! solid data alone that made those two leaves read softer still. Two regimes inside the
//! calibrated ranges read beyond the targets and now carry a warning with their measured band
//! ([`known_bias_warnings_state_the_measured_bands`]); outside them every reference meets the
//! bending, torsion and axial targets.
//!
//! The warping constant's blank slope and the eighth design. An eighth design ([`DOE8`],
//! `--eighth`, `default_rng(20261205)`: 12 circular and 12 corner-filleted rows by the fourth
//! set's rule, 8 short wide corner-filleted leaves with sharp fillets, R/t 0.5–0.8, and 6 narrow
//! circular notches, w/t 0.5–1.1: the two regimes that still missed) was committed before the
//! torsion law's warping constant took a spread slope of its own in the blank proper, 0.84,
//! with the bending's 1/2 in the notch (`hinge::torsion::solid`: one number replacing 0.57, the
//! minimax of the torsion error over the 116 corner-filleted rows of [`DOE1`] to [`DOE7`] and
//! the first calibration); [`DOE8`] was not compared with flexfem before that law was
//! committed, and was then compared once. So [`DOE8`] is held out from every law, and [`DOE7`]
//! is now seen by the blank slope's fit. On [`DOE8`] the corner-filleted hinges meet the
//! bending, torsion and axial targets on every row, its 8 short wide leaves with sharp fillets
//! included (torsion −7.61 … +4.16 %), and miss the peak-stress target on one long leaf with
//! sharp fillets (−5.28 %); the circular notches meet every target but torsion on 4 narrow
//! notches (up to +12.70 %, too stiff, in the regime that warns). A ninth design
//! (`tools/ccx_heldout9_doe.json`, `--ninth`, `default_rng(20261206)`) was committed before
//! [`DOE8`] was compared, for any law changed after it.
//!
//! Compact waists and the ninth design. After [`DOE8`]'s comparison a compact waist
//! (w/t ≲ 1.7, the Saint-Venant warping mode) stopped carrying Vlasov's warping restraint
//! (`hinge::torsion::solid`: no number fitted; the narrow circular notches of [`DOE1`] to
//! [`DOE8`], w/t ≤ 1.1, read +3.1 … +12.7 % with it and −4.8 … +1.1 % without). That law was
//! committed before the ninth design ([`DOE9`]) was compared; [`DOE9`] was then compared once.
//! So [`DOE9`] is held out from every law, and [`DOE8`] is seen by the compact-waist change. On
//! [`DOE9`] every circular notch meets every target (the 8 narrow ones −4.09 … +1.30 % in
//! torsion); the corner-filleted hinges meet bending and peak stress, and two short wide leaves
//! with sharp fillets miss torsion (−10.10 %) and axial (−5.39 %, −6.68 %).
//!
//! Plane strain in the blank and the tenth design. Over the 22 short wide leaves of [`DOE1`] to
//! [`DOE9`] the errors grew with h/t: the taller the blank, the more of the compliance lies in
//! the blank's load-spreading zone, which took E. A tenth design ([`DOE10`], `--tenth`,
//! `default_rng(20261207)`: 12 short wide leaves with sharp fillets in tall blanks, 6 with the
//! usual blanks, 6 circular and 6 corner-filleted rows by the second set's ranges) was
//! committed before that zone took the waist's plane-strain restraint with the local effective
//! thickness as its edge layer (`hinge::solid_effects`: no number fitted; chosen on the rows of
//! [`DOE1`] to [`DOE9`], where the short wide leaves went from bending −3.94 … +0.54 and axial
//! −6.68 … −0.25 % to −2.01 … +2.08 and −3.56 … +1.36 %). That law was committed before
//! [`DOE10`] was compared; [`DOE10`] was then compared once, and [`DOE9`] is now seen. On
//! [`DOE10`] bending meets 3 % everywhere (its tall-blank leaves −2.96 … +0.71 %), but the
//! tall-blank leaves still read too soft in torsion (−12.29 … −3.62 %, 5 of 12 beyond 10 %)
//! and in axial (−5.67 … −0.44 %, 3 beyond 5 %, those with the shortest blanks). An eleventh
//! design (`tools/ccx_heldout11_doe.json`, `--eleventh`, `default_rng(20261208)`) was committed
//! after that comparison, for the next law.
//!
//! The warping constant's blank slope refitted. Over the 39 short wide leaves of [`DOE1`] to
//! [`DOE10`] the torsion error grew with h/t (r = −0.76) and with the blank's shortness (b/h, r = +0.55), and in the
//! flexfem model the blank carries most of such a leaf's torsional compliance (its notch
//! alone, blanks rigid, is 1.9–6.9 times stiffer than the CalculiX model): the blank slope of
//! the warping constant, the one number fitted there, was refitted as the minimax of the torsion
//! error over all 176 corner-filleted rows of [`DOE1`] to [`DOE10`] (0.84 → 1.11,
//! `hinge::torsion::solid`; 1.0 and 1.3 give 9.39 and 9.46 %): −8.68 … +8.65 %, the short wide
//! leaves −6.78 … +7.63 % (from −12.29 … +6.46 %), circular notches moved by at most +0.15 %.
//! The fit uses [`DOE10`], which is seen from then on; the eleventh design, solved before the
//! fit, is its judge. A twelfth (`tools/ccx_heldout12_doe.json`, `--twelfth`,
//! `default_rng(20261209)`: 8 long wide leaves with sharp fillets, the fit's other extreme, 8
//! short wide ones in tall blanks, 6 circular and 8 corner-filleted rows) was drawn and committed
//! before the eleventh was compared, for a law changed after that comparison.
//!
//! The eleventh design compared once ([`DOE11`]): its 6 circular notches and the 9 corner-
//! filleted rows outside the short wide regime meet every target, and peak stress is met on
//! every row; but its short wide leaves in the tallest blanks (h/t 6.8–8.1) still read too soft:
//! torsion down to −12.67 % (5 of 14 beyond 10 %), bending down to −3.87 % (3 beyond 3 %; the
//! worst row's own reference is uncertain by 2.1 % in bending) and axial down to −5.45 % (2
//! beyond 5 %). The refit moved the torsion band of the regime, not its trend with h/t.
//!
//! The torsion law's two slopes refitted together. The Saint-Venant torque's load-spreading
//! slope (1.3 since the first calibration, fitted on the n = 4 stiffnesses of 74 rows) and the
//! warping constant's blank slope were refitted together as the minimax of the torsion error
//! over every corner-filleted row of [`DOE1`] to [`DOE11`] and the fits (200 rows): 1.6 and 1.0
//! (`hinge::torsion::solid`; the minimum, 8.74–8.75 %, runs along a valley from (1.55, 1.05) to
//! (1.65, 0.95), and its centre is taken). A faster spreading of the torque stiffens tall blanks
//! more than low ones: the corner-filleted rows read −8.42 … +8.75 % (the short wide leaves from
//! −12.67 … +7.63 %), the circular notches −8.30 … +6.91 %. [`DOE11`] is seen from then on; the
//! twelfth design, committed before this fit, is its judge. The short wide regime then warned
//! with its bending and axial bands.
//!
//! The twelfth design compared once ([`DOE12`], after the joint refit; its references converged
//! as the others: n = 4, n = 3, n = 6 on its 13 short or wide leaves, converged peaks): torsion
//! meets 10 % on all 30 rows, its 8 leaves in tall blanks (6 in the regime) −6.24 … +1.87 % (the same
//! kind of leaf read down to −12.67 % on the eleventh design before the refit) and its 8 long
//! wide leaves with sharp fillets, the fit's other extreme, +5.31 … +9.09 % (too stiff, inside
//! the target); its circular notches meet every target and peak stress is met on every row.
//! Bending misses 3 % on one leaf just outside the short wide regime (l2.4/R0.6/t1.05/w8.9/h6.9,
//! w/l 3.7: −3.00 %, whose root-refined eighth reads 1.72 % below its reference) and axial 5 % on
//! one short wide leaf in a short blank (−5.32 %, in the regime's band). A thirteenth design
//! (`tools/ccx_heldout13_doe.json`, `--thirteenth`, `default_rng(20261210)`: 10 short wide leaves
//! with sharp fillets in tall short blanks, 8 long leaves with sharp fillets of moderate width),
//! committed before this comparison, is [`PENDING`] for the next law.
//!
//! The bending reference's upper bound. Every bending miss left (the twelfth design's −3.00 %,
//! the eleventh's −3.87, −3.23, −3.08 %) is a short leaf with sharp fillets whose root-refined
//! symmetric eighth ([`PEAKS`], meshed by the fillet radius) reads bending 1.5–2.1 % below the
//! n = 4/6 extrapolation of its full model. A conforming displacement model (C3D10 with the rigid
//! end face) is stiffer than the body it discretises, so the eighth is an upper bound on the true
//! bending stiffness (k = 12 → 16 moves it by at most 0.03 % on the 103 models solved at k = 16,
//! not asserted), and where it lies below
//! the extrapolation the extrapolation is known to be too stiff: [`converged_stiffness`] takes
//! the lower of the two ([`eighth_bending`]; no number chosen; 40 of the 378 references then, 39
//! of them corner-filleted; 50 of 408 with the thirteenth design). Against it bending meets 3 %
//! on every reference of every design (corner-filleted −2.25 … +2.97 %, circular notches
//! −0.62 … +2.77 %), and the short wide regime warned with its axial band alone (with its
//! torsion band too since the thirteenth design). Torsion and axial have no such bound here (the
//! eighths are solved for bending and peak stress only).
//!
//! The corner fillet's peak law. After the twelfth comparison the peak stress missed 5 % on one
//! long leaf with sharp fillets (−5.28 %), and the long mid-width leaves with sharp fillets read
//! 2–5 % low. An 85-notch CalculiX sweep, one dimension at a time (tests/hinge_peak_sweep.rs),
//! showed the narrow notch's K_t, the wide notch's plane-strain shedding and a long flat's root
//! amplification separately; the law fitted on it and on the first twelve designs
//! (`flexfem::hinge::stress::stress_factor`) was then judged once on the thirteenth design
//! ([`DOE13`]: peak −0.79 … +1.35 %, its 8 long leaves with sharp fillets −0.52 … +0.83 %) and,
//! with no law changed in between, on the fourteenth ([`DOE14`]: −1.01 … +1.58 %, its 8 long
//! sharp leaves −0.66 … +1.05 %). Both designs meet every target outside the short wide regime;
//! inside it their 18 leaves in tall short blanks (h/t 6.3–9.0, blank length 0.5–1 h) read
//! torsion down to −12.23 % (3 beyond 10 %) and axial down to −6.90 % (7 beyond 5 %), too soft.
//! The torque's spreading then took the rigid end face's section reaching back into the blank
//! (`hinge::torsion::solid`, slope 0.4 fitted on the fourteen designs): torsion within 10 % on
//! every reference (−8.30 … +9.32 %; the 26 short wide leaves in tall short blanks of all the
//! designs, h/t ≥ 6.3 and b/h ≤ 1, −5.92 … +5.84 %); the regime warns with
//! its axial band alone. A fifteenth design ([`DOE15`], `tools/ccx_heldout15_doe.json`,
//! `--fifteenth`, `default_rng(20261212)`: 10 more such leaves), committed after the thirteenth
//! comparison and before any law aimed at these misses, was then compared once: torsion within
//! 10 % on every row (its 10 leaves in tall short blanks −7.02 … +8.31 %, −10.14 … −4.35 %
//! without the end-face term), bending, peak stress and circular notches within every target,
//! but axial down to −7.48 % on those leaves (4 beyond 5 %): the regime's axial band widened to
//! −7.48 … +1.36 % over 93 models. The axial load then took its own, faster spreading into the
//! blank (`hinge::profile::AXIAL_BLANK_SLOPE` = 0.56, the minimax over all 468 references):
//! axial −3.98 … +4.15 % on every reference, every target met on every circular and
//! corner-filleted reference, and the short wide regime no longer warns.
//!
//! Beyond the designs' box. A sixteenth design ([`DOE16`]: leaves in blanks 0.3–0.5 h long and
//! 10–14 t tall, past the end-face term's box), held out from the axial law, then read every
//! target inside the box and missed beyond it (torsion up to +21.50 %, axial −5.82 %); those
//! hinges get range warnings (blanks shorter than 0.5 h, corner-filleted h/t above 10) and are
//! checked apart ([`held_out`], [`CORNER_BEYOND_TOL`]). A seventeenth ([`DOE17`]: circular
//! notches in tall short blanks, where the end-face term first acts on circular notches, and
//! leaves in tall short blanks, the axial law's regime), fitted on by no law, read every target
//! on every row inside the ranges, and on its 5 circular notches beyond them too. Its first look
//! showed that n = 3 can be far too coarse (n = 4 up to 40 % above the n = 3/4 extrapolation):
//! every reference where n = 4 lies more than 5 % from it is now re-solved at n = 6
//! (`tools/ccx_refine.py`). An eighteenth ([`DOE18`]: corner-filleted leaves with the usual
//! fillets in tall very short and very tall blanks, circular notches in tall very short
//! blanks), drawn before the seventeenth was compared and fitted on by no law (none beyond the
//! ranges was fitted: no simple form brought the sixteenth's 16 leaves within the torsion
//! target), was compared once with the current model: every target met inside the ranges; its
//! 6 circular notches beyond them within every target too, and its 14 leaves beyond them too
//! but one, a leaf with sharp fillets in a very tall blank (+17.78 % torsion): the misses beyond
//! the ranges are leaves with sharp fillets. One of its circular notches showed that n = 4 can
//! be pre-asymptotic too (n = 4 → 6 −31 %, 6 → 8 −0.21 %): where n = 4 → 6 exceeds 5 % the
//! reference is re-solved at n = 8 and takes the n = 6/8 extrapolation ([`N8_RESULTS`]; the
//! re-solve followed a first reading of +33.3 % bending on that notch against the n = 4/6
//! extrapolation, and the rule, by convergence alone, picks that reference only). A
//! nineteenth (`tools/ccx_heldout19_doe.json`, the eighteenth's ranges), drawn before the
//! eighteenth was compared, judged the widening below.
//!
//! A widening of the ranges, tried and reverted. After the eighteenth comparison every miss
//! beyond the first ranges had been a leaf with sharp fillets (R/t ≤ 0.76), while 11 circular
//! notches in blanks 0.31–0.48 h long and 8 leaves with R/t 1.0–2.25 in blanks down to 0.31 h
//! and up to 15.9 t tall met every target; so the ranges were widened there (circular notches
//! to 0.3 h; R/t 1–2.5 to 0.3 h and h/t 16). The nineteenth design ([`DOE19`]), drawn before,
//! judged it once: a leaf inside the widened box (l8.15/R1.5/t1.5/w19.5/h15.05/b7.3, R/t 1.0,
//! blank 0.49 h, h/t 10.03) read torsion +11.32 % with no warning, and a circular notch in a
//! short blank could not be judged then (its reference was not converged by n = 8; at n = 10 it
//! is: [`PRE_ASYMPTOTIC_N6_ROWS`]).
//! The widening was reverted; the first ranges and their warnings stand. Inside them
//! [`DOE19`] met every target (circular −0.05 … +1.43 / −5.41 … −0.76 / +0.86 … +3.71 /
//! −1.36 … +1.86, corner-filleted −1.16 … +1.66 / −1.44 … +9.69 / +0.11 … +2.27 /
//! −0.76 … +0.78 %).
//!
//! These references are ours (computed here with a solver that is not ours), so each
//! comparison is a cross-check of the beam model against solid models of the same geometry.
//!
//! The two solid pipelines agree (see [`solid_pipelines_agree`]): on the three hinges computed
//! by both, CalculiX and scikit-fem differ by at most 0.31 % in stiffness and 1.1 % in peak
//! nodal-averaged stress. So where flexfem disagrees with CalculiX it disagrees with the
//! scikit-fem models too: the beam model's side is the one to fix, not the solid references.
//! What differs between solid set-ups is the stress definition: the peak at the integration
//! points of C3D10 lies 4–12 % below the nodal-averaged peak (on all rows but the narrowest
//! notch, R3/t0.8/w0.5, whose integration-point peak is 52 % above its nodal one: one distorted
//! element, not investigated) (the integration points sit inside
//! the element, the peak is on the surface), which is the size of the peak-stress disagreement
//! a comparison with integration-point stresses shows. flexfem's peak stress is compared with
//! the nodal-averaged peak, as in tests/hinge_solid_reference.rs.

use flexfem::hinge::{characterise, HingeSpec};
use flexfem::material::Material;

#[path = "hinge_ccx_reference/references.rs"]
mod references;
use references::{converged_value, richardson, CcxRef, FIRST_FIT, FIRST_HELD_OUT};
#[path = "hinge_ccx_reference/doe.rs"]
mod doe;
use doe::DOE1;
#[path = "hinge_ccx_reference/doe2.rs"]
mod doe2;
use doe2::DOE2;
#[path = "hinge_ccx_reference/doe3.rs"]
mod doe3;
use doe3::DOE3;
#[path = "hinge_ccx_reference/doe4.rs"]
mod doe4;
use doe4::DOE4;
#[path = "hinge_ccx_reference/doe5.rs"]
mod doe5;
use doe5::DOE5;
#[path = "hinge_ccx_reference/doe6.rs"]
mod doe6;
use doe6::DOE6;
#[path = "hinge_ccx_reference/doe7.rs"]
mod doe7;
use doe7::DOE7;
#[path = "hinge_ccx_reference/doe8.rs"]
mod doe8;
use doe8::DOE8;
#[path = "hinge_ccx_reference/doe9.rs"]
mod doe9;
use doe9::DOE9;
#[path = "hinge_ccx_reference/doe10.rs"]
mod doe10;
use doe10::DOE10;
#[path = "hinge_ccx_reference/doe11.rs"]
mod doe11;
use doe11::DOE11;
#[path = "hinge_ccx_reference/doe12.rs"]
mod doe12;
use doe12::DOE12;
#[path = "hinge_ccx_reference/doe13.rs"]
mod doe13;
use doe13::DOE13;
#[path = "hinge_ccx_reference/doe14.rs"]
mod doe14;
use doe14::DOE14;
#[path = "hinge_ccx_reference/doe15.rs"]
mod doe15;
use doe15::DOE15;
#[path = "hinge_ccx_reference/doe16.rs"]
mod doe16;
use doe16::DOE16;
#[path = "hinge_ccx_reference/doe17.rs"]
mod doe17;
use doe17::DOE17;
#[path = "hinge_ccx_reference/doe18.rs"]
mod doe18;
use doe18::DOE18;
#[path = "hinge_ccx_reference/doe19.rs"]
mod doe19;
use doe19::DOE19;

#[path = "hinge_ccx_reference/raw.rs"]
mod raw;
use raw::{raw_lines_matched, SCIKIT_FEM};
#[path = "common/raw_results.rs"]
mod raw_results;
use raw_results::{json_lines, matching_lines};

struct Row {
    spec: HingeSpec,
    /// Errors of flexfem against CalculiX, %: bending, torsion, axial, peak stress per moment.
    err: [f64; 4],
}

fn rows(refs: &[&CcxRef]) -> Vec<Row> {
    refs.iter()
        .map(|r| {
            let spec: HingeSpec = serde_json::from_str(r.hinge).unwrap_or_else(|e| panic!("{}: {e}", r.hinge));
            let m = Material {
                e: r.e,
                nu: r.nu,
                ..Material::AL7075
            };
            let h = characterise(&spec, &m)
                .unwrap_or_else(|e| panic!("{}: {e}", r.hinge))
                .hinge;
            let pct = |a: f64, b: f64| 100.0 * (a - b) / b;
            let [k_bend, k_torsion, k_axial] = converged_stiffness(r);
            let peak = converged_peak(r).unwrap_or(r.spm_nodal);
            let err = [
                pct(h.k_bend, k_bend),
                pct(h.k_torsion, k_torsion),
                pct(h.k_axial, k_axial),
                pct(h.stress_per_moment, peak),
            ];
            println!(
                "{:<100} bend {:+6.2} %  torsion {:+6.2} %  axial {:+6.2} %  stress/moment {:+6.2} % (vs integration points {:+6.2} %)",
                r.hinge,
                err[0],
                err[1],
                err[2],
                err[3],
                pct(h.stress_per_moment, r.spm_ip)
            );
            Row { spec, err }
        })
        .collect()
}

/// The converged stiffnesses (bending, torsion, axial) of a reference: the order-2 Richardson
/// extrapolation of n = 8 and n = 10 where the reference was re-solved at n = 10
/// ([`N10_RESULTS`]), of n = 6 and n = 8 where it was re-solved at n = 8
/// ([`N8_RESULTS`]), of n = 4 and n = 6 where it was re-solved at n = 6
/// ([`N6_RESULTS`]), of n = 3 and n = 4 otherwise ([`CcxRef::converged`]). The finer pair is
/// the better one where it exists: on short corner-filleted leaves with small fillets the n = 3
/// mesh is too coarse for the asymptotic rate and the n = 3/4 extrapolation over-corrects (see
/// [`extrapolation_checked_on_finer_meshes`]).
fn converged_stiffness(r: &CcxRef) -> [f64; 3] {
    static LINES: std::sync::OnceLock<[Vec<serde_json::Value>; 2]> = std::sync::OnceLock::new();
    static LINES10: std::sync::OnceLock<Vec<serde_json::Value>> = std::sync::OnceLock::new();
    let [n6, n8] = LINES.get_or_init(|| [json_lines(N6_RESULTS), json_lines(N8_RESULTS)]);
    let n10 = LINES10.get_or_init(|| json_lines(N10_RESULTS));
    let stiffnesses = |lines: &[serde_json::Value], n: u32| {
        let hits = matching_lines(lines, r.hinge, r.e, r.nu, &[], |_| true);
        assert!(hits.len() <= 1, "{}: {} n = {n} lines", r.hinge, hits.len());
        hits.first()
            .map(|&i| ["k_bend", "k_torsion", "k_axial"].map(|q| lines[i][q].as_f64().unwrap()))
    };
    let k6 = stiffnesses(n6, 6);
    let mut k = match (k6, stiffnesses(n8, 8), stiffnesses(n10, 10)) {
        (Some(_), Some(k8), Some(k10)) => std::array::from_fn(|q| richardson(k10[q], k8[q], 10.0, 8.0)),
        (Some(k6), Some(k8), None) => std::array::from_fn(|q| richardson(k8[q], k6[q], 8.0, 6.0)),
        (None, Some(_), _) => panic!("{}: an n = 8 line without an n = 6 one", r.hinge),
        (_, None, Some(_)) => panic!("{}: an n = 10 line without an n = 8 one", r.hinge),
        _ => r.converged(k6),
    };
    if let Some(eighth) = eighth_bending(r) {
        k[0] = k[0].min(eighth);
    }
    k
}

/// The compliant-axis bending stiffness of a reference's root-refined symmetric eighth
/// ([`PEAKS`]), N·mm/rad. A conforming displacement model (C3D10, rigid end face) is stiffer
/// than the elastic body it discretises, so this is an upper bound on the true stiffness: where
/// it lies below the extrapolated full model, the extrapolation is known to be too stiff, and
/// [`converged_stiffness`] takes the bound instead (on 50 of the 408 references up to [`DOE13`],
/// by up to 2.10 %: short leaves with sharp fillets whose full models at n = 6 do not yet
/// resolve the root; the eighth moves by at most 0.03 % from k = 12 to k = 16 on the 103 models
/// solved at k = 16, 3 of the first 40; not asserted). The [`PEAKS`] lines of [`PENDING`] designs are read too: no compared
/// reference shares their geometries.
fn eighth_bending(r: &CcxRef) -> Option<f64> {
    eighths(r)
        .iter()
        .map(|l| l["k_bend"].as_f64().unwrap())
        .reduce(f64::min)
}

/// The [`PEAKS`] lines of a reference's geometry (its root-refined symmetric eighths), read
/// once for [`eighth_bending`] and [`converged_peak`].
fn eighths(r: &CcxRef) -> Vec<&'static serde_json::Value> {
    static LINES: std::sync::OnceLock<Vec<serde_json::Value>> = std::sync::OnceLock::new();
    let lines = LINES.get_or_init(|| json_lines(PEAKS));
    matching_lines(lines, r.hinge, r.e, r.nu, &[], |_| true)
        .into_iter()
        .map(|i| &lines[i])
        .collect()
}

/// The references re-solved at n = 6 (`tools/ccx_refine.py --n 6`).
const N6_RESULTS: &str = "ccx_refine_n6_results.jsonl";
/// The references re-solved at n = 8 as well (`tools/ccx_refine.py --n 8`): those where n = 4
/// and n = 6 differ by more than 5 % in bending, so that n = 4 is not yet in the asymptotic
/// range and the n = 4/6 extrapolation cannot be trusted; the tables take the n = 6/8 one.
const N8_RESULTS: &str = "ccx_refine_n8_results.jsonl";
/// The references re-solved at n = 10 as well (`tools/ccx_refine.py --n 10`): those where n = 6
/// and n = 8 still differ by more than 5 % in bending; the tables take the n = 8/10
/// extrapolation.
const N10_RESULTS: &str = "ccx_refine_n10_results.jsonl";

/// Designs solved but not yet compared with flexfem (held out for the next law): their
/// `_results.jsonl` files under `tools/`. Their lines in the re-solve files (n = 3, n = 6,
/// converged peaks) are committed as they are solved and skipped by the checks here
/// ([`compared_lines`]) until the design gets its test module and joins [`DESIGNS`].
const PENDING: [&str; 0] = [];

/// The lines of a re-solve file under `tools/` whose reference is not of a [`PENDING`] design.
fn compared_lines(file: &str) -> Vec<serde_json::Value> {
    json_lines(file)
        .into_iter()
        .filter(|l| !PENDING.iter().any(|p| l["source"] == *p))
        .collect()
}

/// Every design's results file under `tools/` is either compared (one of [`DESIGNS`]) or
/// [`PENDING`], never both, and a pending one holds lines; every line of the re-solve files
/// (n = 3, n = 6, converged peaks) is of a compared or pending design or of the first fit's
/// references.
#[test]
fn every_results_file_is_compared_or_pending() {
    let compared: Vec<String> = DESIGNS
        .iter()
        .map(|(stem, ..)| format!("{stem}_results.jsonl"))
        .collect();
    for p in PENDING {
        assert!(!compared.iter().any(|c| c == p), "{p} is compared");
        assert!(!json_lines(p).is_empty(), "{p}");
    }
    let mut designs = 0;
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/tools")).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if name.starts_with("ccx_heldout") && name.ends_with("_results.jsonl") {
            assert!(
                compared.contains(&name) || PENDING.contains(&name.as_str()),
                "{name}: neither compared nor pending"
            );
            designs += 1;
        }
    }
    assert_eq!(designs, DESIGNS.len() + PENDING.len());
    for file in [
        "ccx_refine_n3_results.jsonl",
        N6_RESULTS,
        N8_RESULTS,
        N10_RESULTS,
        PEAKS,
    ] {
        for l in json_lines(file) {
            let source = l["source"]
                .as_str()
                .unwrap_or_else(|| panic!("{file}: a line without source"));
            assert!(
                source == "ccx_reference_results.jsonl"
                    || compared.iter().any(|c| c == source)
                    || PENDING.contains(&source),
                "{file}: a line of {source}"
            );
        }
    }
}

/// The converged peak stress per moment of a circular or corner-filleted reference, MPa/(N·mm):
/// its line of `tools/ccx_peak_stress_k12.jsonl` (the symmetric eighth with the mesh sized by
/// the notch root, `tools/ccx_peak_stress.py`; see [`converged_peaks_checked`]). `None` for the
/// turned necks, whose peak stays the n = 4 one.
fn converged_peak(r: &CcxRef) -> Option<f64> {
    let peaks: Vec<f64> = eighths(r)
        .iter()
        .map(|l| l["stress_per_moment_nodal"].as_f64().unwrap())
        .collect();
    // A geometry solved twice (two references of the same hinge) agrees to the mesh's noise.
    assert!(
        peaks.iter().all(|p| (p / peaks[0] - 1.0).abs() < 0.01),
        "{}: {peaks:?}",
        r.hinge
    );
    peaks.first().copied()
}

/// Prints the range of each error over `rows` (the figures the README quotes) and returns the
/// largest |error| per quantity, %.
fn report(label: &str, rows: &[&Row]) -> [f64; 4] {
    let mut worst = [0.0; 4];
    let mut text = format!("{label} (n = {}):", rows.len());
    for (q, name) in ["bending", "torsion", "axial", "peak stress per moment"]
        .iter()
        .enumerate()
    {
        let lo = rows.iter().map(|r| r.err[q]).fold(f64::INFINITY, f64::min);
        let hi = rows.iter().map(|r| r.err[q]).fold(f64::NEG_INFINITY, f64::max);
        worst[q] = lo.abs().max(hi.abs());
        text += &format!(" {name} {lo:+.2} … {hi:+.2} %,");
    }
    println!("{text}");
    worst
}

/// Asserts |error| < tolerance per quantity (bending, torsion, axial, peak stress, %).
fn check(label: &str, worst: [f64; 4], tol: [f64; 4]) {
    for q in 0..4 {
        let name = ["bending", "torsion", "axial", "peak stress per moment"][q];
        assert!(
            worst[q] < tol[q],
            "{label}: {name} off by up to {:.2} %, tolerance {} %",
            worst[q],
            tol[q]
        );
    }
}

fn family(rows: &[Row], f: fn(&HingeSpec) -> bool) -> Vec<&Row> {
    rows.iter().filter(|r| f(&r.spec)).collect()
}

fn circular(s: &HingeSpec) -> bool {
    matches!(s, HingeSpec::CircularNotch { .. })
}

fn corner(s: &HingeSpec) -> bool {
    matches!(s, HingeSpec::CornerFilleted { .. })
}

fn neck(s: &HingeSpec) -> bool {
    matches!(s, HingeSpec::SphericalNeck { .. })
}

/// CalculiX against scikit-fem on the same mesh generator: stiffnesses within 0.5 % (measured
/// +0.15 … +0.31 % bending and torsion, +0.06 … +0.13 % axial), nodal-averaged peak stress
/// within 1.5 % (measured −1.07 … +0.68 %). And the integration-point peak of C3D10 lies 5–12 %
/// below the nodal-averaged one on these three hinges (measured 6.62 … 7.96 %; the
/// stress-definition difference).
#[test]
fn solid_pipelines_agree() {
    let all: Vec<&CcxRef> = FIRST_FIT.iter().chain(FIRST_HELD_OUT).collect();
    let mut worst = [0.0f64; 2];
    for (hinge, sk) in SCIKIT_FEM {
        let spec: serde_json::Value = serde_json::from_str(hinge).unwrap();
        let same: Vec<&&CcxRef> = all
            .iter()
            .filter(|r| serde_json::from_str::<serde_json::Value>(r.hinge).unwrap() == spec)
            .collect();
        assert_eq!(same.len(), 1, "{hinge}");
        let c = same[0];
        let ccx = [c.k_bend, c.k_torsion, c.k_axial, c.spm_nodal];
        let d: Vec<f64> = (0..4).map(|q| 100.0 * (ccx[q] / sk[q] - 1.0)).collect();
        println!(
            "{hinge}: ccx vs scikit-fem bend {:+.2} %, torsion {:+.2} %, axial {:+.2} %, nodal peak stress {:+.2} %",
            d[0], d[1], d[2], d[3]
        );
        worst[0] = worst[0].max(d[0].abs()).max(d[1].abs()).max(d[2].abs());
        worst[1] = worst[1].max(d[3].abs());
    }
    assert!(
        worst[0] < 0.5,
        "stiffness: ccx and scikit-fem differ by {:.2} %",
        worst[0]
    );
    assert!(
        worst[1] < 1.5,
        "nodal peak stress: ccx and scikit-fem differ by {:.2} %",
        worst[1]
    );
    let below: Vec<f64> = SCIKIT_FEM
        .iter()
        .map(|(hinge, _)| {
            let spec: serde_json::Value = serde_json::from_str(hinge).unwrap();
            let c = all
                .iter()
                .find(|r| serde_json::from_str::<serde_json::Value>(r.hinge).unwrap() == spec)
                .unwrap();
            100.0 * (1.0 - c.spm_ip / c.spm_nodal)
        })
        .collect();
    assert_eq!(below.len(), 3);
    let (lo, hi) = below
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    println!("integration-point peak below the nodal-averaged peak by {lo:.2} … {hi:.2} %");
    assert!(lo > IP_BELOW_NODAL.0 && hi < IP_BELOW_NODAL.1, "{lo:.2} … {hi:.2} %");
}

/// Every reference is a line of the raw CalculiX results (same geometry, E and ν, the five
/// quantities to the 6 digits copied here), and no two references share a geometry.
#[test]
fn every_reference_is_a_line_of_the_raw_results() {
    let first: Vec<&CcxRef> = FIRST_FIT.iter().chain(FIRST_HELD_OUT).collect();
    assert_eq!(raw_lines_matched("ccx_reference_results.jsonl", &first), 50);
    for (stem, refs, rows, _) in DESIGNS {
        let file = format!("{stem}_results.jsonl");
        assert_eq!(
            raw_lines_matched(&file, &refs.iter().collect::<Vec<_>>()),
            rows,
            "{file}"
        );
    }
}

/// The fresh designs of experiments: file stem under `tools/` (`_doe.json` the design,
/// `_results.jsonl` its CalculiX results), the references, their number, how many are circular
/// notches.
const DESIGNS: [(&str, &[CcxRef], usize, usize); 19] = [
    ("ccx_heldout", DOE1, 24, 12),
    ("ccx_heldout2", DOE2, 24, 12),
    ("ccx_heldout3", DOE3, 20, 4),
    ("ccx_heldout4", DOE4, 24, 12),
    ("ccx_heldout5", DOE5, 24, 12),
    ("ccx_heldout6", DOE6, 24, 12),
    ("ccx_heldout7", DOE7, 32, 12),
    ("ccx_heldout8", DOE8, 38, 18),
    ("ccx_heldout9", DOE9, 32, 16),
    ("ccx_heldout10", DOE10, 30, 6),
    ("ccx_heldout11", DOE11, 30, 6),
    ("ccx_heldout12", DOE12, 30, 6),
    ("ccx_heldout13", DOE13, 30, 6),
    ("ccx_heldout14", DOE14, 30, 6),
    ("ccx_heldout15", DOE15, 30, 6),
    ("ccx_heldout16", DOE16, 30, 6),
    ("ccx_heldout17", DOE17, 30, 14),
    ("ccx_heldout18", DOE18, 32, 12),
    ("ccx_heldout19", DOE19, 32, 12),
];

/// The fresh rows are the committed designs of experiments, in their order
/// (`tools/ccx_heldout_doe.json`, `tools/ccx_heldout2_doe.json`: the same geometry, 12
/// circular notches then 12 corner-filleted hinges each; `tools/ccx_heldout3_doe.json`: 16
/// corner-filleted hinges then 4 circular notches).
#[test]
fn fresh_rows_are_the_committed_designs() {
    for (stem, refs, _, n_circular) in DESIGNS {
        let file = format!("{stem}_doe.json");
        let text = std::fs::read_to_string(format!("{}/tools/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let design: Vec<serde_json::Value> = serde_json::from_str(&text).unwrap();
        assert_eq!(design.len(), refs.len(), "{file}");
        for (d, r) in design.iter().zip(refs) {
            let spec: serde_json::Value = serde_json::from_str(r.hinge).unwrap();
            for (k, v) in spec.as_object().unwrap() {
                let same = match (d[k].as_f64(), v.as_f64()) {
                    (Some(a), Some(b)) => a == b,
                    _ => d[k] == *v,
                };
                assert!(same, "{file}: {}: {k} = {} in the design", r.hinge, d[k]);
            }
        }
        let n_circ = refs.iter().filter(|r| r.hinge.contains("circular_notch")).count();
        assert_eq!(n_circ, n_circular, "{file}");
    }
}

/// The integration-point peak lies this far below the nodal-averaged peak on the hinges of
/// [`SCIKIT_FEM`], %.
const IP_BELOW_NODAL: (f64, f64) = (5.0, 10.0);

// The issue's targets (bending, torsion, axial, peak stress, %): circular notches and
// corner-filleted hinges 3 / 10 / 5 / 5, on the held-out rows and on the rows fitted; turned
// necks as today's held-out bands against the scikit-fem models, 3 / 5 / 3 / 3. Where the beam
// model misses a target the tolerance below is the measured worst case rounded up (a pin that
// shows a change), and the comment says by how much the target is missed.

/// The issue's targets for circular notches and corner-filleted hinges.
const TARGET: [f64; 4] = [3.0, 10.0, 5.0, 5.0];
/// The 12 circular notches of [`DOE18`] (6 in tall very short blanks, 0.31–0.48 h long, h/t
/// 10.7–20.6, then beyond the ranges; 6 by the second set's ranges), fitted on by no law and
/// compared once with the current model: the 6 inside the ranges −0.07 … +2.00 / −5.88 … +7.47 /
/// +0.67 … +2.44 / −0.24 … +3.46, the 6 beyond them −0.48 … +0.68 / −6.83 … +5.60 /
/// −2.57 … +0.85 / +0.90 … +2.80: every target met. ([`DOE18`]'s R1.1/t0.35/w5.8/h7.2 first read
/// +33.3 % bending and +17.1 % torsion against its n = 4/6 extrapolation, its n = 4 mesh not yet
/// asymptotic; against n = 6/8 +0.65 and +5.60 %: see [`PRE_ASYMPTOTIC_N6_TO_N8`].)
/// The 6 circular notches of [`DOE19`] by the second set's ranges (its other 6, in tall very short
/// blanks, beyond them; one of those converged only at n = 10, [`PRE_ASYMPTOTIC_N6_ROWS`]),
/// fitted on by no law and compared once:
/// −0.05 … +1.43 / −5.41 … −0.76 / +0.86 … +3.71 / −1.36 … +1.86: every target met.
/// The 9 circular notches of [`DOE17`] inside the calibrated ranges (3 of its 8 in tall short
/// blanks, R 1.25–2.8, h/t 10.5–21, blank length 0.54–0.67 h, where the rigid end faces' torque
/// term acts on a circular notch for the first time, and 6 by the second set's ranges), fitted on
/// by no law and compared once with the current model after its references converged (a first
/// look, before, prompted the n = 6 re-solves of its 8 circular notches in tall short blanks, as
/// a group, and of one leaf, chosen by their convergence alone; see
/// [`extrapolation_checked_on_finer_meshes`]): −0.64 … +1.99 / −8.22 … +4.96 /
/// −1.61 … +3.15 / −1.43 … +4.40: every target met. Its other 5, in blanks shorter than 0.5 h,
/// were beyond the ranges then (see [`DOE18`]'s above). (A first look before its references
/// converged read bending +39.8 and +13.8 % on two of them: their n = 3 meshes were too coarse,
/// n = 4 lying 40.0 and 14.5 % above the n = 3/4 extrapolation against 0.9 and 1.4 % above the
/// n = 4/6 one; see [`extrapolation_checked_on_finer_meshes`].)
/// 6 circular notches of [`DOE16`], drawn and committed before the axial load's spreading into
/// the blank, held out from it and compared once: −0.00 … +1.79 / −6.89 … +0.32 / +0.28 … +4.71 /
/// −1.30 … +2.09: every target met.
/// The 6 circular notches of [`DOE15`], drawn and committed before the rigid end faces' reach into
/// the blank for the torque, held out from every law and compared once with the model of that day:
/// +0.01 … +1.66 / −7.64 … −0.35 / +0.32 … +3.48 / −1.35 … +1.72: every target met.
/// The 6 circular notches of [`DOE14`], drawn and committed before the corner fillet's peak law and
/// before [`DOE13`] was compared, held out from every law and compared once with the frozen
/// model: −0.10 … +1.79 / −5.75 … +5.80 / −0.02 … +2.67 / −0.35 … +2.53: every target met.
/// The 6 of [`DOE13`], drawn and committed before the torsion law's two slopes were
/// refitted together and before the corner fillet's peak law, held out from every law and
/// compared once with the frozen model: +0.01 … +2.09 / −7.21 … +6.85 / +0.51 … +1.99 /
/// +0.24 … +3.56: every target met.
/// The 6 circular notches of [`DOE12`], drawn and committed before the torsion law's two slopes
/// were refitted together, held out from every law and compared once with the frozen model:
/// +0.05 … +1.26 / −6.20 … +1.27 / +0.33 … +2.94 / −0.39 … +2.54: every target met.
/// The 6 of [`DOE11`], drawn, committed and solved before the warping constant's
/// blank slope was refitted, held out from every law and compared once with the frozen model:
/// −0.37 … +2.00 / −5.62 … +0.93 / +0.10 … +3.17 / −0.79 … +2.18: every target met.
/// The 6 of [`DOE10`] (−7.59 … +2.10 % torsion since the refits of the torsion slopes, which used
/// corner-filleted rows only), drawn and
/// committed before the blank's spreading zone took
/// the plane-strain restraint (`hinge::solid_effects`), held out from every law and compared
/// once with the frozen model: −0.62 … +1.14 / −7.55 … +1.96 / −0.24 … +3.29 / −1.47 … +2.63:
/// every target met.
const CIRCULAR_TOL: [f64; 4] = TARGET;
/// The circular notches outside the calibrated ranges, which warn (blanks shorter than 0.5 h):
/// [`DOE17`]'s 5, [`DOE18`]'s 6 and [`DOE19`]'s 6, −0.48 … +0.77 / −8.36 … +8.16 /
/// −2.57 … +0.85 / +0.66 … +3.79: every target met. Pinned at 1 / 8.4 / 2.6 / 3.8 %. (A widening
/// of the circular notches' blank range to 0.3 h, chosen on the first 11 after [`DOE18`]'s
/// comparison, was judged by [`DOE19`] and reverted: its sixth notch there could not be judged
/// then, its reference not converged by n = 8; it joined at n = 10 ([`PRE_ASYMPTOTIC_N6_ROWS`])
/// at +0.22 / +8.16 / −2.31 / +3.79 %, moving the band's torsion from +5.60 and its peak from
/// +3.75.)
const CIRCULAR_BEYOND_TOL: [f64; 4] = [1.0, 8.4, 2.6, 3.8];
/// The 16 circular notches of [`DOE9`] (8 by the second set's ranges, 8 narrow: w/t 0.5–1.1),
/// drawn and committed before [`DOE8`] was compared and before a compact waist stopped carrying
/// warping restraint, held out from those laws and compared once with the frozen model:
/// −0.08 … +1.54 / −7.02 … +1.30 / −0.02 … +3.35 / −1.38 … +3.08: every target met, the 8
/// narrow notches −4.09 … +1.30 % in torsion (they read up to +12.7 % on the earlier designs
/// before the change). Seen since by the blank's plane-strain restraint, and measured with it:
/// −0.08 … +1.54 / −7.02 … +1.30 / −0.02 … +3.48 / −1.38 … +3.08. With that law the 52 of
/// [`DOE3`] to [`DOE7`] read −0.21 … +2.69 / −8.31 … +5.77 / −0.96 … +3.95 / −1.59 … +3.64
/// and the 18 of [`DOE8`] −0.43 … +2.29 / −6.43 … +1.90 / −0.18 … +2.56 / −0.84 … +2.89
/// (bending and axial moved by at most +0.44 and +0.89 %).
/// 52 circular notches: 40 of [`DOE3`] (4; t/R 0.10–0.40, w/t 0.80–12.6, blank w/h 0.11–2.3),
/// [`DOE4`], [`DOE5`] and [`DOE6`] (12 each), each compared once with the model of its day and
/// held out of every fit but the warping slope's, seen before the later changes (the torsion
/// law's warping spreading after DOE4 and DOE6, the axial law after DOE5). Measured now:
/// −0.21 … +2.33 / −8.31 … +8.99 / −0.96 … +3.84 / −1.59 … +3.64: every target met. (At their
/// comparisons: DOE3 + DOE4 axial +0.33 … +4.30, DOE5 −0.10 … +1.56 / −7.40 … +8.29 /
/// +1.13 … +4.23 / −0.97 … +4.15 against n = 4 peaks, DOE6 −0.21 … +2.33 / −6.54 … +8.87 /
/// −0.96 … +3.29 / −1.59 … +3.29; before the warping spreading, DOE3 + DOE4 torsion
/// −8.22 … +7.79.) And the 12 of [`DOE7`]:
/// drawn and committed before the warping spread slope was
/// fitted, held out from that law and compared once with the frozen model, then seen by the
/// warping constant's blank slope fit. At that comparison, against the converged stiffnesses
/// ([`converged_stiffness`]) and the converged peaks of [`PEAKS`], bending / torsion / axial /
/// peak σ/M, %: −0.00 … +1.56 / −8.25 … +11.31 / −0.68 … +2.44 / +0.16 … +2.88; measured now
/// −0.00 … +1.56 / −8.20 … +11.39 / −0.68 … +2.44 / +0.16 … +2.88. **Torsion misses 10 % on 1
/// of 12**: R11.15/t3.25/w2.6/h24.7, a narrow (w/t 0.80), deep notch, +11.39 % (too stiff):
/// pinned then at 11.4 %. It is the regime of the circular notches' other high readings
/// (w/t ≤ 1.1: +3.1 … +9.5 % on the earlier designs), where the warping constant is small and
/// its spreading does not matter (with the earlier slope 1/2 the row reads +11.05 %, measured
/// after the comparison); that regime warned until a compact waist stopped carrying warping
/// restraint. [`DOE3`] to [`DOE7`] together, with the warping constant's blank slope:
/// −0.21 … +2.33 / −8.31 … +11.39 / −0.96 … +3.84 / −1.59 … +3.64; since a compact waist
/// carries no warping restraint (see [`CIRCULAR_TOL`]): torsion −8.31 … +5.77 %, every target
/// met.
/// The 18 circular notches of [`DOE8`] (12 by the usual rule, 6 narrow: w/t 0.5–1.1), drawn and
/// committed before the warping constant's blank slope was fitted, held out from every law and
/// compared once with the frozen model (against the n = 4/6 extrapolations where a reference
/// was re-solved at n = 6, n = 3/4 otherwise, and converged peaks): −0.43 … +2.02 /
/// −6.43 … +12.70 / −0.88 … +2.56 / −0.84 … +2.89. **Torsion misses 10 % on 4 of 18, every one
/// a narrow notch (w/t 0.58–0.76), too stiff**: R6.15/t1.8/w1.05 +12.70 %, R4.2/t1/w0.6
/// +11.22 %, R3.35/t0.85/w0.65 +10.47 %, R3.15/t1/w0.7 +10.28 %. The 14
/// others read −6.43 … +7.71 % in torsion, the 9 outside the narrow regime (w/t > 1.1)
/// −6.43 … +2.67 %. The narrow regime then warned, and the tolerance was pinned at 12.8 %.
/// After that comparison a compact waist (w/t ≲ 1.7) stopped carrying warping restraint
/// (`hinge::torsion::solid`, no number fitted, chosen on the narrow notches of [`DOE1`] to
/// [`DOE8`]): the 18 now read −0.43 … +2.02 / −6.43 … +1.90 / −0.88 … +2.56 / −0.84 … +2.89,
/// every target met, the narrow ones −4.81 … +1.14 % in torsion.
const CIRCULAR_SEEN_TOL: [f64; 4] = TARGET;
/// The 20 corner-filleted hinges of [`DOE18`] (8 leaves by the second set's fillet and flat
/// ranges in tall very short blanks, 0.31–0.48 h, and 6 in very tall blanks, h/t 10.7–15.9: all
/// 14 beyond the calibrated ranges, checked with [`CORNER_BEYOND_TOL`]; 6 by the second set's
/// ranges), fitted on by no law and compared once with the current model: the 6 inside the
/// ranges −0.41 … +1.41 / −2.28 … +3.92 / +0.43 … +2.36 / −1.51 … +1.74, every target met.
/// The 20 corner-filleted hinges of [`DOE19`] (the same kinds; its 14 aimed ones beyond the
/// ranges), fitted on by no law and compared once: the 6 inside the ranges −1.16 … +1.66 /
/// −1.44 … +9.69 / +0.11 … +2.27 / −0.76 … +0.78, every target met. (It judged, and refuted, a
/// widening of the ranges for R/t 1–2.5 chosen after [`DOE18`]'s comparison: its
/// l8.15/R1.5/t1.5/w19.5/h15.05/b7.3, R/t 1.0 in a blank 0.49 h long, read torsion +11.32 %.)
const CORNER_TOL: [f64; 4] = TARGET;
/// The corner-filleted hinges outside the calibrated ranges, which warn: [`DOE16`]'s 16 (below),
/// [`DOE18`]'s 14 and [`DOE19`]'s 14, together −2.37 … +0.84 / −10.74 … +21.50 / −5.82 … +0.05 /
/// −1.14 … +1.56: pinned at 3 / 21.6 / 5.9 / 1.6 %. [`DOE18`]'s 14, with the second set's fillets (R/t
/// 0.56–2.25) where [`DOE16`]'s had sharp ones (R/t 0.50–0.76), read far closer: in blanks
/// 0.31–0.48 h long −1.60 … +0.83 / +1.39 … +8.80 / −4.53 … +0.05 / −1.08 … +1.17, every target
/// met; in blanks 10.7–15.9 t tall −2.27 … +0.23 / −3.20 … +17.78 / −3.58 … −0.86 /
/// −1.06 … +1.49, torsion missing 10 % on one leaf with sharp fillets
/// (l5.35/R0.75/t1.35/w10.35/h16.55/b8.75, R/t 0.56, h/t 12.3: +17.78 %). The misses beyond the
/// ranges are leaves with sharp fillets.
/// 24 corner-filleted hinges of [`DOE16`] (10 short wide leaves with sharp fillets in tall very
/// short blanks: 4–8 t above the fillets, blank length 0.31–0.49 h; 6 in very tall blanks, h/t
/// 10.3–13.7, blank length 0.53–0.94 h; 8 by the second set's ranges), drawn and committed before
/// [`DOE15`] was compared and before the axial load's spreading into the blank, held out from it
/// and compared once with the model of that day: −2.37 … +1.60 / −10.74 … +21.50 / −5.82 … +2.70 /
/// −0.97 … +0.92. **The axial law holds** on every row in the designs' box (the 8 second-set rows
/// and the rest in blanks ≥ 0.5 h long with h/t ≤ 10) and bending and peak stress meet the
/// targets on every row. **Beyond the box the model misses**: in blanks shorter than 0.5 h
/// torsion reads +2.32 … +21.50 % (the rigid end faces' term, which the `hinge` analysis warns
/// is extrapolated there, over-stiffens: without it they read −11.22 … −3.52 %) and axial
/// −5.82 … −1.48 % (2 beyond 5 %); in blanks taller than 10 t torsion reads −10.74 … +19.74 %.
/// Every such row gets the end-face warning and a range warning (blank_length/h below 0.5, or
/// corner-filleted h/t above 10: `hinge::calibration::short_blank_warning`, `CORNER_H_OVER_T`).
/// Its 8 rows inside the ranges read −0.91 … +1.60 / −2.81 … +6.05 / −0.03 … +2.70 /
/// −0.97 … +0.92 and are a seen design since ([`CORNER_SEEN_TOL`]).
const CORNER_BEYOND_TOL: [f64; 4] = [3.0, 21.6, 5.9, 1.6];
/// The 16 corner-filleted hinges of [`DOE17`] (8 short wide leaves with sharp fillets in tall short
/// blanks, 4–8 t above the fillets, blank length 0.5–1 h: the regime the axial load's spreading
/// into the blank was fitted on; 8 by the second set's ranges), fitted on by no law and compared
/// once with the current model: −2.05 … +0.93 / −5.04 … +6.78 / −2.34 … +2.10 / −0.51 … +0.53:
/// **every target met on every row**, the 8 leaves in tall short blanks axial −2.34 … −0.60 %.
/// Compared once after its references converged: a first look before (the model unchanged
/// since) read bending +5.06 % on l3.55/R1.55/t1.25/w9.8/h7.75/b6.0, whose n = 3 mesh was too
/// coarse: n = 4 lay 6.2 % above the n = 3/4 extrapolation, 1.6 % above the n = 4/6 one, so it
/// was re-solved at n = 6 by the rule of `tools/ccx_refine.py`; against that reference it reads
/// +0.47 %. A seen design since [`DOE18`]'s comparison.
/// The 24 corner-filleted hinges of [`DOE15`] (10 short wide leaves with sharp fillets in tall short
/// blanks: 4–8 t above the fillets, h/t 6.4–9.8, blank length 0.52–0.96 h; 6 short wide leaves
/// with sharp fillets and the usual blanks; 8 by the second set's ranges), drawn and committed
/// right after [`DOE13`] was compared and before the rigid end faces' reach into the blank for
/// the torque (`hinge::torsion::solid::TORSION_FACE_SLOPE`, fitted on [`DOE1`] to [`DOE14`]),
/// held out from every law and compared once with the model of that day: −2.23 … +1.30 /
/// −7.02 … +9.67 / −7.48 … +1.52 / −0.65 … +1.06. **The end-face law holds on fresh data:**
/// torsion within 10 % on every row; its 10 leaves in tall short blanks read −7.02 … +8.31 %
/// (without the term −10.14 … −4.35 %, one beyond 10 %). Bending and peak stress meet the
/// targets on every row. **Axial misses 5 % on 4 of the 10 leaves in tall short blanks**
/// (l2.4/R0.65/t1.2/w20.9/h11.75/b7.5, h/t 9.8, b/h 0.64: −7.48 %; −5.54, −5.30, −5.13 %; too
/// soft, in the short wide regime, whose warned axial band widens to −7.48 … +1.36 % over 93
/// models), and a fifth, l4.7/R1.0/t1.95/w17.9/h17.05/b9.45 (w/l 3.8, just outside the
/// regime), reads −4.999 %. Pinned then at 3 / 10 / 7.5 / 1.6 %. Seen since by the axial load's
/// spreading into the blank (`hinge::profile::AXIAL_BLANK_SLOPE`, 0.56, fitted on these rows
/// among all 468): axial −3.98 … +2.38 %, every target met on every row; pinned at the targets,
/// the peak at 1.6 %; then a seen design.
/// The 24 corner-filleted hinges of [`DOE14`] (8 short wide leaves with sharp fillets in tall short
/// blanks: 4–7 t above the fillets, h/t 6.3–9.0, blank length 0.5–1 h; 8 long leaves with sharp
/// fillets: R/t 0.50–0.69, flat 2.7–7.5 t, w/t 3.3–9.3; 8 by the second set's ranges), drawn and
/// committed before the corner fillet's peak law and before [`DOE13`] was compared, held out
/// from every law and compared once with the frozen model (no law changed between the two
/// comparisons): −1.94 … +1.12 / −10.97 … +9.32 / −5.96 … +1.51 / −1.01 … +1.58. **The peak
/// law holds a second time**: the 8 long leaves with sharp fillets read −0.66 … +1.05 % in peak
/// stress and meet every target; bending and peak stress meet the targets on every row, and the
/// 16 rows outside the short wide regime meet every target (torsion −5.35 … +9.32 %). **The
/// tall short blanks stay too soft**: of the 8 short wide leaves in them torsion misses 10 % on 2
/// (l3.5/R1.05/t1.75/w18.65/h15.7/b11.6, h/t 9.0, −10.97 %; l2.5/R0.85/t1.25/w10.6/h9.35/b5.3,
/// −10.15 %) and axial 5 % on 3 (−5.96, −5.42, −5.33 %), inside the regime's warned bands
/// (unchanged by these 8: torsion −12.23 … +8.75, axial −6.90 … +1.36 % over 79 models).
/// Pinned then at 3 / 11 / 6 / 1.6 %. Seen since by the rigid end face's reach into the blank
/// for the torque (`hinge::torsion::solid::TORSION_FACE_SLOPE`, 0.4, fitted on these rows
/// among others): torsion −4.94 … +9.32 %, within 10 % on every row. Since [`DOE15`]'s
/// comparison it is a seen design ([`CORNER_SEEN_TOL`]).
/// The 24 corner-filleted hinges of [`DOE13`] (10 short wide leaves with sharp fillets in tall short
/// blanks: 4–7 t above the fillets, h/t 6.5–9.0, blank length 0.5–1 h; 8 long leaves with sharp
/// fillets: R/t 0.52–0.59, flat 3–8 t, w/t 3–10; 6 by the second set's ranges), drawn and
/// committed before the torsion law's two slopes were refitted together, before [`DOE12`] was
/// compared and before the corner fillet's peak law, held out from every law and compared once
/// with the frozen model: −1.85 … +1.97 / −12.23 … +6.98 / −6.90 … +0.97 / −0.79 … +1.35.
/// **The peak law holds**: the 8 long leaves with sharp fillets, the regime it was built for
/// (K_t^0.27/√P read them down to −5.28 % before), read −0.52 … +0.83 % in peak stress, and
/// every target is met on them (torsion +0.95 … +6.98 %). Bending and peak stress meet the
/// targets on every row, and the 13 rows outside the short wide regime meet every target (its
/// 11 short wide leaves are the 10 in tall short blanks and one with the usual blank, which
/// meets every target too).
/// **The tall short blanks stay too soft**: of the 10 short wide leaves in them, torsion misses
/// 10 % on 1 (l2.2/R0.85/t1.1/w12.15/h9.9/b6.3, h/t 9.0, the tallest blank yet: −12.23 %; the
/// others −9.82 … −1.66 %) and axial 5 % on 4 (−6.90, −5.93, −5.61, −5.17 %: the leaves whose
/// blanks are shortest for their height, b/h 0.52–0.68; the five with b/h ≥ 0.73 read
/// −4.33 … −3.35 %, one with b/h 0.59 −3.29 %). All are in the short wide regime, which warns with the band now measured on 71
/// models (torsion −12.23 … +8.75, axial −6.90 … +1.36 %). Pinned then at 3 / 12.3 / 7.0 /
/// 1.4 %; since it joined the seen designs, its axial misses set [`CORNER_SEEN_TOL`]'s axial pin
/// (7.0 %). With the rigid end face's reach into the blank for the torque (0.4, fitted on these
/// rows among others) its torsion reads −5.24 … +6.98 %, the −12.23 % leaf −2.18 %.
/// The 24 corner-filleted hinges of [`DOE12`] (8 long wide leaves with sharp fillets: flat 3–8 t,
/// w/t 10–20; 8 short wide leaves with sharp fillets in tall blanks, 3–6 t above the fillets; 8
/// by the second set's ranges), drawn and committed before the torsion law's two slopes were
/// refitted together (and before [`DOE11`] was compared), held out from every law and compared
/// once with the frozen model: −3.00 … +1.34 / −6.24 … +9.09 / −5.32 … +1.50 / −2.28 … +3.90.
/// Torsion meets 10 % on every row: the tall-blank leaves −6.24 … +1.87 %, the long wide leaves
/// with sharp fillets +5.31 … +9.09 % (too stiff). Peak stress meets the target on every row.
/// **Bending misses 3 % on 1 of 24 and axial 5 % on 1**: l2.4/R0.6/t1.05/w8.9/h6.9/b5.3, a
/// short leaf in a tall blank just short of the regime's width (w/l 3.7), −3.00 % bending
/// (its root-refined eighth reads bending 1.72 % below the n = 4/6 extrapolation, so against the
/// finer mesh it reads about −1.3 %); l2.7/R1.0/t1.35/w22.75/h8.4/b4.6, a short wide leaf in a
/// short blank (b/h 0.55), −5.32 % axial, inside the band the regime's warning states. Pinned
/// then at 3.1 / 10 / 5.4 / 5 %. Against the bending reference's upper bound (the root-refined
/// eighth where it is softer than the extrapolation, [`eighth_bending`], taken after this
/// comparison; no number chosen) they read −2.25 … +1.34 % in bending, the −3.00 % leaf
/// −1.30 %: every bending target met. Pinned at 3 / 10 / 5.4 / 5 %. Seen since by the corner
/// fillet's peak law (fitted on these rows among others; see [`CORNER_SEEN_TOL`]): peak
/// stress −0.81 … +1.24 %, within [`CORNER_SEEN_TOL`].
/// The 24 corner-filleted hinges of [`DOE11`] (14 short wide leaves with sharp fillets in tall
/// blanks, 3–6 t above the fillets: h/t 5.3–8.1, blank length 0.5–2 h; 4 with the usual blanks;
/// 6 by the second set's ranges), drawn, committed and solved before the warping constant's
/// blank slope was refitted (0.84 → 1.11 on [`DOE1`] to [`DOE10`]), held out from every law and
/// compared once with the frozen model: −3.87 … +1.54 / −12.67 … +6.60 / −5.45 … +1.34 /
/// −4.51 … +1.92. Peak stress meets the target on every row, and the 9 rows outside the
/// short wide regime meet every target. **The refit did not carry to the tallest blanks**:
/// torsion misses 10 % on 5 of the 14 tall-blank leaves (l2.4/R0.75/t1.2/w10.6/h8.2 −12.67 %,
/// l3.0/R0.85/t1.5/w16.1/h10.75 −11.03 %, l2.1/R0.65/t1.05/w15.65/h8.5 −10.90 %,
/// l3.85/R1.2/t1.6/w16.1/h12.5 −10.89 %, l3.7/R1.25/t1.85/w22.65/h14.65 −10.38 %: h/t 6.8–8.1,
/// beyond the tenth design's 7.3 only on three), bending misses 3 % on 3 (−3.87, −3.23,
/// −3.08 %) and axial 5 % on 2 (−5.45, −5.25 %), all too soft. The −3.87 % leaf's root-refined
/// eighth reads bending 2.10 % below its n = 4/6 extrapolation ([`EIGHTH_BEND_TOL`]), so
/// against the finer mesh it reads about −1.8 %: its reference is uncertain by that much. The
/// 4 tall-blank leaves with blanks longer than 1.2 h read −3.15 … +2.21 % in torsion; 4 of
/// the 5 misses have blanks of 0.5–0.8 h. Pinned
/// then at 3.9 / 12.7 / 5.5 / 5 %. Seen since by the joint refit of the torsion law's two slopes
/// (1.6 and 1.0, fitted on these rows among others), with which they read −3.87 … +1.54 /
/// −8.42 … +7.30 / −5.45 … +1.34 / −4.51 … +1.92: torsion meets 10 % on every row; pinned at
/// 3.9 / 10 / 5.5 / 5 %; against the bending reference's upper bound ([`eighth_bending`])
/// bending −1.81 … +1.54 %, within [`CORNER_SEEN_TOL`]. The regime warns with its measured band
/// ([`known_bias_warnings_state_the_measured_bands`]), and a twelfth design
/// (`tools/ccx_heldout12_doe.json`, committed before this comparison) judged the next law.
/// The 24 corner-filleted hinges of [`DOE10`] (12 short wide leaves with sharp fillets in tall
/// blanks, 3–5 t above the fillets: h/t 5.2–7.3; 6 with the usual blanks; 6 by the second set's
/// ranges), drawn and committed before the blank's spreading zone took the plane-strain
/// restraint, held out from every law and compared once with the frozen model:
/// −2.96 … +2.21 / −12.29 … +6.34 / −5.67 … +1.88 / −0.41 … +2.27. Bending and peak stress
/// meet the targets (the 12 tall-blank leaves −2.96 … +0.71 % in bending, where the earlier
/// designs' short wide leaves in tall blanks read down to −3.94 % before the law). **Torsion
/// misses 10 % on 5 of the 12 tall-blank leaves and axial misses 5 % on 3, all too soft**:
/// l2.9/R0.75/t1.45/w19.05/h9.45/b7.1 −12.29 % torsion, l2.3/R0.6/t1.15/w19/h6.2/b3.3 −12.18 /
/// −5.67 %, l2.4/R0.8/t1.1/w21.2/h6.85/b4.05 −12.17 / −5.31 %, l3.55/R0.95/t1.75/w31.2/h10.55/
/// b7.05 −11.99 / −5.24 %, l3.25/R1.05/t1.35/w12.1/h9.8/b10.4 (w/l 3.7, just outside the
/// warned regime) −10.76 % torsion: pinned at 12.3 / 5.7 %. The axial misses are the leaves with
/// the shortest blanks for their height (blank length 0.5–0.7 h); those with blank lengths
/// above h read −0.4 … −2.5 %. The 6 short wide leaves with the usual blanks meet every target
/// (torsion −7.37 … +6.34 %). The regime warns with its measured band
/// ([`known_bias_warnings_state_the_measured_bands`]), and an eleventh design
/// (`tools/ccx_heldout11_doe.json`) is committed for the next law. Seen since by the refit of
/// the warping constant's blank slope (0.84 → 1.11, fitted on these rows among others), with
/// which they read −2.96 … +2.21 / −8.68 … +7.28 / −5.67 … +1.88 / −0.41 … +2.27: torsion
/// meets 10 % on every row; axial still misses on the 3 leaves with the shortest blanks,
/// pinned at 5.7 % in [`CORNER_SEEN_TOL`].
/// The 16 corner-filleted hinges of [`DOE9`] (8 by the second set's ranges, 8 short wide
/// leaves with sharp fillets: w/l 4.2–9.4, l/t 2.0–2.9, R/t 0.52–0.77), held out from the laws
/// before it and compared once with the frozen model: −2.27 … +0.70 / −10.10 … +7.07 /
/// −6.68 … +0.78 / −1.12 … +3.23: l2.3/R0.8/t1.15/w13.75/h6.8 (the tallest blank of the eight,
/// h/t 5.9) −10.10 % torsion and −5.39 % axial, l2.5/R0.7/t1.25/w23.6/h5.25 (w/l 9.4) −6.68 %
/// axial, all too soft. Seen since by the blank's plane-strain restraint (chosen on the short
/// wide leaves of [`DOE1`] to [`DOE9`]), with which they read −1.24 … +1.70 / −10.10 … +7.07 /
/// −3.56 … +1.36 / −1.12 … +3.23: **torsion still misses 10 % on that leaf** (−10.10 %), pinned
/// at 10.2 %. With the law the 72 of [`DOE3`] to [`DOE7`] below read −2.01 … +2.97 /
/// −7.53 … +6.33 / −3.46 … +1.70 / −1.77 … +3.87 and the 20 of [`DOE8`] −1.26 … +2.08 /
/// −7.61 … +6.93 / −2.28 … +1.13 / −5.28 … +3.45: bending and axial now meet the targets on
/// every seen row (the two R/t 0.52 leaves that missed bending, −3.94 %, read −1.84 and
/// −2.01 %).
/// 72 corner-filleted hinges: 52 of [`DOE3`] (16; l/t 2.0–9.5, R/t 0.57–2.4 (12 of them ≥ 1.2),
/// w/t 1.2–16.6, blank w/h 0.22–3.9, blank length 0.54–1.8 h), [`DOE4`], [`DOE5`] and [`DOE6`]
/// (12 each), as the circular ones above (held out of the K_t refit and of the axial fit, seen
/// by the warping slope's). Measured before the blank slope: −3.94 … +1.20 / −11.35 … +5.41 /
/// −4.31 … +1.03 / −1.77 … +3.72. **Bending and torsion missed on 1 of 52**: [`DOE6`]'s
/// l2.7/R0.7/t1.35/w18.55/
/// h6.9, the other short wide leaf with R/t 0.52 (−3.94 / −11.35 %; −0.89 / −9.35 % against its
/// n = 3/4 extrapolation, which is 3.1 / 2.2 % below its n = 4/6 one), pinned then at 4.0 /
/// 11.4 %.
/// At their comparisons torsion missed 10 % on one row of [`DOE5`] (l3.55/R0.8/t1.3/w17.9/h5.3,
/// −10.88 %, now −5.76 %) and on that row of [`DOE6`] (−13.29 %); before the warping spreading
/// first changed, DOE4's torsion read −2.28 … +12.37 % (a wide leaf, l6.65/R0.85/t1.2/w16.5/h7.3,
/// +12.37 %, and a short narrow one, l2.2/R0.9/t1.1/w1.25, +11.13 %): the comparison that
/// prompted that change.
/// Axial: with E alone DOE3 + DOE4 read −5.60 … +2.78 % (the wide leaf above −5.60 %, a miss)
/// and DOE5 −4.81 … +2.39 %; the axial modulus E·(1 + 0.6(P − 1))/G (`hinge::solid_effects`, the
/// share 0.6 fitted on the FIT rows only) takes them to −3.02 … +1.16 %. (Tried before it and not
/// adopted: the full bending modulus E·P/G, which read circular notches +5.27 % on the fits.)
/// (Against the n = 4 stiffnesses DOE3 read bending −2.21 … +0.13 %; before the fillets got the
/// short-notch factor G it read −0.38 … +4.88 %, 6 of 16 above 3 %, so this test fails with that
/// law.)
/// With the warping constant's blank slope (fitted on these rows among others): torsion
/// −6.89 … +7.74 %, within 10 %; [`DOE6`]'s R/t 0.52 leaf still misses bending (−3.94 %),
/// pinned at 4.0 %. And the 20 of [`DOE7`]:
/// (12 by the usual rule, 8 short wide leaves: w/l
/// 3.0–7.2, l/t 2.0–3.5, R/t 0.52–1.14), held out from every law and compared once with the
/// frozen model. At that comparison (against the n = 3/4 extrapolations): −1.32 … +2.26 /
/// −13.97 … +6.68 / −5.16 … +0.73 / −1.75 … +3.87, torsion and axial missing on 1 of 20.
/// Measured now, against the n = 4/6 extrapolations where the reference was re-solved at n = 6
/// (every short or wide leaf of the design): −3.94 … +2.26 / −17.12 … +6.52 / −6.53 … +0.79 /
/// −1.75 … +3.87. **Bending, torsion and axial miss on 1 of 20**: l3.15/R0.7/t1.35/w22.75/h7.5,
/// the shortest, widest leaf with the sharpest fillets of the design (w/l 7.2, l/t 2.3, R/t
/// 0.52), −3.94 / −17.12 / −6.53 % (all too soft), pinned then at 4.0 / 17.2 / 6.6 %. Its own
/// references are uncertain by more than elsewhere (n = 3/4 and n = 4/6 extrapolations differ
/// by 3.2 / 3.7 / 1.4 %, and its root-refined eighth reads bending 1.0 % below the n = 4/6
/// value), but not by the miss. The other 7 short wide leaves read −9.10 … +3.43 % in torsion.
/// With the earlier slope 1/2 the design reads −19.62 … +6.38 % against the n = 3/4
/// references (measured after the comparison): the refit took the short wide leaves most of
/// the way, not all of it. The shortest, widest leaves with sharp fillets (R/t ≈ 0.5) in tall
/// blanks stay too soft, as both earlier misses were; that regime now warns
/// ([`known_bias_warnings_state_the_measured_bands`]).
/// With the warping constant's blank slope (fitted on these rows among others, after this
/// comparison) they read −3.94 … +2.26 / −7.53 … +6.92 / −6.53 … +0.79 / −1.75 … +3.87: torsion
/// now meets 10 %; that leaf still misses bending and axial.
/// All 72 together, measured now: −3.94 … +2.26 / −7.53 … +7.74 / −6.53 … +1.03 /
/// −1.77 … +3.87: the two R/t 0.52 leaves miss bending (−3.94 %), one of them axial (−6.53 %),
/// pinned at 4.0 / 6.6 %; both are in the short wide regime, which warns.
/// And the 20 corner-filleted hinges of [`DOE8`] (12 by the usual rule, 8 short wide leaves
/// with sharp fillets: w/l 3.3–9.5, l/t 2.0–2.9, R/t 0.52–0.78), drawn and committed before the
/// warping
/// constant's blank slope was fitted, held out from every law and compared once with the frozen
/// model: −2.39 … +0.43 / −7.61 … +6.93 / −4.60 … +0.61 / −5.28 … +3.45. Bending, torsion and
/// axial meet the targets on every row, the 8 short wide leaves included (−2.39 … +0.27 /
/// −7.61 … +4.16 / −4.60 … −0.09; the same regime read −17.1 % torsion with the slope 0.57
/// everywhere). **Peak stress misses 5 % on 1 of 20**: l8.6/R0.7/t1.35/w8.8/h5.25, a long leaf
/// with sharp fillets (R/t 0.52), −5.28 % (too low: unconservative): pinned at 5.3 %.
/// (Unchanged since, as a compact waist stopped carrying warping restraint: torsion
/// −7.61 … +6.93 %.)
/// With the warping constant's blank slope refitted on [`DOE1`] to [`DOE10`] (0.84 → 1.11):
/// torsion [`DOE3`] to [`DOE7`] −6.75 … +8.20, [`DOE8`] −6.55 … +8.48, [`DOE9`] −5.82 … +8.65 %
/// (its −10.10 % leaf now within 10 %): every torsion target met; the pin is the target.
/// With the torsion law's two slopes refitted together on [`DOE1`] to [`DOE11`] (1.6 and 1.0):
/// torsion [`DOE3`] to [`DOE7`] −6.36 … +8.10, [`DOE8`] −3.69 … +8.26, [`DOE9`]
/// −3.62 … +8.75, [`DOE10`] −5.36 … +7.91 %.
/// Peak stress: with the corner fillet's peak law refitted (K_t = 1 + 0.24·t/(2R) of the narrow
/// notch, times 1 − 0.71·(P − 1) and the long-leaf root amplification,
/// `hinge::stress::stress_factor`; the minimax fit over these rows, [`DOE12`]'s and the
/// one-dimension sweep of `tests/hinge_peak_sweep.rs`): [`DOE3`] to [`DOE7`] −1.56 … +1.98,
/// [`DOE8`] −0.70 … +1.64 (its −5.28 % leaf −0.48 %), [`DOE9`] −0.83 … +1.65, [`DOE10`]
/// −0.38 … +1.02, [`DOE11`] −1.39 … +0.86 %; pinned at 2.0 % (K_t^0.27/√P read
/// −4.51 … +3.90 % on them).
/// Axial: [`DOE10`]'s 3 short-blank leaves, −5.67 % (above), pinned then at 5.7 %. Bending:
/// [`DOE11`]'s leaf in the tallest blank read −3.87 % (above); against the bending reference's
/// upper bound ([`eighth_bending`]) [`DOE11`] reads −1.81 … +1.54 %, [`DOE10`]
/// −1.57 … +2.21 %, [`DOE3`] to [`DOE7`] −1.49 … +2.97 %: every bending target met.
/// Torsion with the rigid end face's reach into the blank for the torque (0.4, fitted on these
/// rows and [`DOE13`]'s and [`DOE14`]'s): [`DOE3`] to [`DOE7`] −6.36 … +8.10, [`DOE8`]
/// −3.69 … +8.26, [`DOE9`] −3.41 … +8.75, [`DOE10`] −5.36 … +7.91, [`DOE11`] −6.64 … +7.30,
/// [`DOE12`] −4.41 … +9.09, [`DOE13`] −5.24 … +6.98, [`DOE14`] −4.94 … +9.32 %: within 10 % on
/// every row. Axial read down to −6.90 % ([`DOE13`]; [`DOE14`] −5.96 %) until the axial load's
/// spreading into the blank (0.56, fitted on all 468 references): [`DOE3`] to [`DOE7`]
/// −1.00 … +2.83, [`DOE8`] −1.53 … +2.58, [`DOE9`] −1.56 … +2.24, [`DOE10`] −3.35 … +2.89,
/// [`DOE11`] −2.53 … +2.19, [`DOE12`] −2.85 … +2.11, [`DOE13`] −3.88 … +2.07, [`DOE14`]
/// −2.90 … +2.21 %: every target met on every row; the peak pinned at 2 %.
const CORNER_SEEN_TOL: [f64; 4] = [3.0, 10.0, 5.0, 2.0];
/// The 50 circular notches of the fits. Measured against the converged stiffnesses and peaks:
/// −0.41 … +2.45 / −7.73 … +6.80 / −0.72 … +3.25 / −1.39 … +3.45: every target met (torsion
/// −7.73 … +9.74 while compact waists carried warping restraint; axial
/// −0.65 … +4.28 with E alone, against the n = 3/4 references; the axial share 0.6 is the
/// minimax fit on these rows and the corner-filleted ones below). (With Γ spread like the
/// Saint-Venant torque, as the torsion law's two numbers were fitted on the n = 4 stiffnesses,
/// torsion read −7.60 … +10.74 %; refitting those two numbers on the converged stiffnesses of
/// all 118 rows then seen reached 10.9 % at best.)
/// With the torsion law's two slopes refitted on eleven designs (1.6 and 1.0): torsion
/// −7.64 … +6.91 %. Now, with every law to date (the axial load's spreading into the blank
/// included): −0.41 … +2.77 / −7.64 … +6.91 / +0.18 … +3.47 / −1.39 … +3.45.
const CIRCULAR_FIT_TOL: [f64; 4] = TARGET;
/// The 44 corner-filleted hinges of the fits. Measured against the converged stiffnesses and
/// peaks: −2.08 … +0.80 / −7.28 … +6.42 / −3.17 … +1.07 / −3.47 … +3.22 (against the n = 3/4
/// references throughout, as the fits were made: −1.63 … +2.20 / −6.98 … +6.85 / −3.23 … +1.10;
/// axial −4.30 … +2.43 with E alone; the K_t exponent 0.27 is the minimax fit on these rows,
/// with the earlier 1/5 −8.05 … +1.19): every target met (before the warping spreading changed,
/// torsion −8.11 … +12.85 %, wide leaves between low blanks l4/R1/t1/w15/h5 and
/// l6/R1.5/t1.5/w30/h6 above 10 %). (Bending read −3.60 % on l5.95/R1.45/t1.95/w10.15/h11.9
/// against its n = 4 stiffness, which is 2 % too stiff: −1.64 % against the extrapolation,
/// −2.17 % against the n = 6/8 one.)
/// With the torsion law's two slopes refitted on eleven designs (1.6 and 1.0): torsion
/// −5.53 … +7.79 %. With the corner fillet's peak law (K_t = 1 + 0.24·t/(2R) times
/// 1 − 0.71·(P − 1) and the long-leaf root amplification, which replaced the exponent 0.27;
/// fitted on these rows among others, see [`CORNER_SEEN_TOL`]): peak stress −1.33 … +1.80 %.
/// Now, with every law to date (the axial load's spreading into the blank included):
/// −1.53 … +1.85 / −5.53 … +7.79 / −0.02 … +2.99 / −1.33 … +1.80.
const CORNER_FIT_TOL: [f64; 4] = TARGET;
/// [`extrapolation_checked_on_finer_meshes`]: the references re-solved at n = 6 (the others;
/// the short or wide corner-filleted leaves; the others whose n = 3 mesh is too coarse, n = 4
/// more than 5 % above the n = 3/4 extrapolation in bending), and how closely the n = 3/4
/// extrapolation agrees with the n = 4/6 one (bending, torsion, axial, %). Measured: within
/// 1.11 / 1.13 / 0.50 % on the 68 others (0.76 / 1.13 / 0.42 % on the 62 with at most 30,000
/// unknowns at n = 4 before [`DOE17`]'s 6 circular notches in tall short blanks);
/// 27.93 / 10.19 / 1.20 % on the 3 with n = 3 too coarse ([`DOE17`]'s circular
/// R2.15/t0.7/w12.1/h10.9 and R1.25/t0.6/w7.8/h6.3, n = 4 40.0 and 14.5 % above the n = 3/4
/// extrapolation, 0.9 and 1.4 % above the n = 4/6 one; its corner-filleted
/// l3.55/R1.55/t1.25/w9.8/h7.75, 6.2 and 1.6 %);
/// within 12.93 / 10.94 / 3.45 % on all 172 short (l/t ≤ 2.75) or wide (w/l > 3) corner-filleted
/// leaves (the same on the 162 before [`DOE17`]'s 10; the sixteenth design's leaves in very tall blanks, h/t up to 13.7, where n = 3 puts
/// too few elements across the blank: n = 4 sits 22.0 % above the n = 3/4 extrapolation in
/// bending on l3.0/R0.85/t1.5/w12.95/h20.6, against 3.3 % from n = 4 to n = 6; 5.40 / 4.67 /
/// 1.93 % on the 144 before them, 5.40 / 4.67 / 1.86 % on the 127 before the fifteenth design's 17, the same on the 118 before the fourteenth design's 9; 4.19 / 4.01 / 1.86 % on the 107 before the thirteenth design's 11, whose tall short
/// blanks widen the gap; the same on the 94 before the twelfth design's 13; 4.02 / 4.01 / 1.67 % on the 74
/// before the eleventh design's 20, 3.16 / 3.67 / 1.44 %
/// on the 55 before the tenth design's 19), the worst short wide
/// leaves with sharp fillets (R/t ≈ 0.5), whose n = 3 mesh is too coarse
/// for the asymptotic rate: there the n = 3/4 extrapolation over-corrects, and the tables take
/// the n = 4/6 one ([`converged_stiffness`]).
/// With [`DOE19`]: 182 short or wide leaves, 5 with n = 3 too coarse (31.26 % bending on its
/// R1.9/t0.75/w12.4/h11.9), 2 with n = 4 not asymptotic (one of them with n = 6 not asymptotic
/// either, [`PRE_ASYMPTOTIC_N6_ROWS`]).
const N6_ROWS: [usize; 4] = [68, 182, 5, 2];
/// The references whose n = 4 is not yet asymptotic (n = 4 → 6 beyond 5 % in bending),
/// re-solved at n = 8 ([`N8_RESULTS`]), and how far n = 6 → 8 moves their bending, % (measured:
/// [`DOE18`]'s circular R1.1/t0.35/w5.8/h7.2/b3.45, bending 3268, 2733, 2085, 2081 N·mm/rad at
/// n = 3, 4, 6, 8: −31.1 % from n = 4 to 6, −0.21 % from 6 to 8; its root-refined eighth reads
/// 2080; against the n = 4/6 extrapolation, 1567, flexfem read +33.3 %, against the n = 6/8
/// one, 2076, it reads +0.65 %).
const PRE_ASYMPTOTIC_ROWS: usize = 2;
/// The references whose n = 6 is not yet asymptotic either (n = 6 → 8 beyond 5 % in
/// bending), re-solved at n = 10 ([`N10_RESULTS`]): [`DOE19`]'s circular
/// R1.1/t0.5/w5.6/h9.05/b4.0, bending 6194, 5195, 4736, 4731 N·mm/rad at n = 4, 6, 8, 10 (−8.8 %
/// from 6 to 8, −0.11 % from 8 to 10; its root-refined eighth, an upper bound, 4727; its curved
/// n = 3 meshes failed). It was left out of every comparison until then: against the n = 6/8
/// extrapolation (4145) flexfem read bending +14.16 % and torsion +15.22 % at the one
/// comparison; against the n = 8/10 one, 4722, bending +0.22 %, torsion +8.16 %. Its torsion
/// gets the end-face warning (+15.7 % term), and its blank (0.44 h) the short-blank warning.
const PRE_ASYMPTOTIC_N6_ROWS: usize = 1;
const PRE_ASYMPTOTIC_N6_TO_N8: f64 = 0.3;
const EXTRAPOLATION_TOL: [f64; 3] = [1.2, 1.2, 0.55];
const COARSE_N3_EXTRAPOLATION_TOL: [f64; 3] = [31.3, 10.3, 1.3];
const SHORT_WIDE_EXTRAPOLATION_TOL: [f64; 3] = [13.0, 11.0, 3.5];
/// The nodal-averaged peak stress from n = 4 to n = 6 on those references, %: measured
/// −7.15 … +24.25 ([`DOE18`]'s leaf in a very tall blank l4.45/R2.0/t1.2/w19.8/h19.1 and its
/// circular R1.1/t0.35/w5.8/h7.2, whose n = 4 mesh is not yet asymptotic; −4.23 … +13.05 before
/// [`DOE18`]'s 7, −4.13 … +13.05 before [`DOE17`]'s 19, −4.13 … +12.05 before the fifteenth design's 17, −4.13 … +10.54 before the thirteenth design's, −4.13 … +10.40 before the twelfth design's, −4.13 … +9.25 before the
/// eleventh design's short wide leaves, −4.13 … +7.30
/// before the tenth's, −1.46 … +7.30 before the ninth's).
const PEAK_N4_TO_N6: (f64, f64) = (-7.2, 24.3);
/// The converged peaks, one line per circular and corner-filleted reference.
const PEAKS: &str = "ccx_peak_stress_k12.jsonl";
/// The same solved at k = 16 (the 103 smaller models, 52 corner-filleted), and how far the peak
/// moved, % (measured 0.71 %).
const PEAKS_K16: &str = "ccx_peak_stress_k16.jsonl";
const PEAKS_K16_ROWS: usize = 103;
const PEAK_K12_TO_K16: f64 = 0.75;
/// The turned necks' nodal peak from n = 4 to 6, ± % (measured 2.12 %).
const NECK_PEAK_N4_TO_N6: f64 = 2.5;
/// The eighth's compliant-axis stiffness lies between the full model's converged and n = 4 ones
/// within this, %: measured at least −1.04 % from the extrapolated one ([`CcxRef::converged`]; not
/// [`converged_stiffness`], which takes this bound), at
/// most −0.03 % from n = 4. Below the converged one by more than 0.15 % only on the two short
/// wide leaves with R/t 0.52 ([`DOE7`]'s l3.15/R0.7/t1.35/w22.75, −1.04 %, and [`DOE6`]'s
/// l2.7/R0.7/t1.35/w18.55, −0.92 %): the eighth's root mesh (R/12) resolves compliance that the
/// full models at n = 6 (t/6) do not yet, so their converged bending is likely that much lower.
/// With [`DOE10`]'s short wide leaves with sharp fillets (R/t 0.52–0.58) the eighth reads down to
/// −1.41 % from the converged one, the same effect: the tolerance went from 1.1 to 1.5 %. With
/// [`DOE11`]'s leaves in the tallest blanks it reads down to −2.10 % (l2.1/R0.65/t1.05/w15.65/
/// h8.5; −1.41 … −1.64 % on four more): the tolerance went to 2.2 %. [`DOE17`]'s
/// l2.3/R0.65/t1.15/w10.9/h8.7, a short wide leaf with sharp fillets in a tall short blank, reads
/// −2.21 %: the tolerance went to 2.3 %.
const EIGHTH_BEND_TOL: f64 = 2.3;
/// Peak-stress convergence pins, % (nodal-averaged, integration point), n = 4 → 5.
/// (family, R mm, nodal-averaged tolerance %, integration-point tolerance %, measured gap %).
#[allow(clippy::type_complexity)]
const CONV_TOL: [(&str, f64, f64, f64, f64); 2] = [
    ("circular_notch", 8.0, 0.6, 2.8, 4.85),
    ("corner_filleted", 2.0, 0.8, 1.5, 6.82),
];
/// 4 turned necks (their model is not fitted on these rows). Measured against the converged
/// stiffnesses (bending / torsion / axial / peak σ/M, %): +0.11 … +1.48 / −1.69 … +0.19 /
/// +0.37 … +0.98 / −2.41 … +1.12 (the axial −0.69 … +0.44 before the axial load's spreading into
/// the blank; earlier +0.78 … +1.88 / −1.02 … +0.52 / −0.26 … +0.52 in bending / torsion / axial).
const NECK_TOL: [f64; 4] = [3.0, 5.0, 3.0, 3.0];

/// Every row computed before the corner-filleted bending law was changed: the first
/// calibration's FIT and HELD_OUT rows and the first two fresh designs ([`DOE1`], [`DOE2`]).
fn fit_rows() -> Vec<Row> {
    rows(
        &FIRST_FIT
            .iter()
            .chain(FIRST_HELD_OUT)
            .chain(DOE1)
            .chain(DOE2)
            .collect::<Vec<_>>(),
    )
}

/// The designs of experiments held out from the law of their day, in the order they were
/// compared: [`DOE3`] to [`DOE7`] are checked together, the later ones each; the last is the
/// fresh design, held out from every law and compared once with the current model.
const HELD_OUT: [(&str, &[CcxRef]); 17] = [
    ("DOE3", DOE3),
    ("DOE4", DOE4),
    ("DOE5", DOE5),
    ("DOE6", DOE6),
    ("DOE7", DOE7),
    ("DOE8", DOE8),
    ("DOE9", DOE9),
    ("DOE10", DOE10),
    ("DOE11", DOE11),
    ("DOE12", DOE12),
    ("DOE13", DOE13),
    ("DOE14", DOE14),
    ("DOE15", DOE15),
    ("DOE16", DOE16),
    ("DOE17", DOE17),
    ("DOE18", DOE18),
    ("DOE19", DOE19),
];

/// How many of [`HELD_OUT`]'s first designs are checked together (DOE3 to DOE7).
const EARLIER: usize = 5;

/// The rigid end faces' term's validated gain (`hinge::calibration::END_FACE_VALIDATED_GAIN`) is
/// the largest on the corner-filleted references inside the ranges of the designs it was set on
/// ([`DOE1`] to [`DOE18`]), rounded up by less than 0.01 %: measured 0.17104, [`DOE15`]'s
/// l4.7/R1.0/t1.95/w17.9/h17.05/b9.45. ([`DOE19`]'s, compared after it was set, reach
/// 0.0294, inside the cap.)
#[test]
fn end_face_validated_gain_is_the_largest_on_the_references() {
    use flexfem::hinge::calibration::END_FACE_VALIDATED_GAIN;
    use flexfem::hinge::torsion::{continuous_ends, solid_torsion_stiffness};
    let gain = |r: &CcxRef| {
        let spec: HingeSpec = serde_json::from_str(r.hinge).unwrap();
        if !corner(&spec) || !in_range(&spec) {
            return 0.0;
        }
        let p = spec.profile().unwrap().with_rigid_end_faces();
        solid_torsion_stiffness(&p, r.e, r.nu) / solid_torsion_stiffness(&continuous_ends(&p), r.e, r.nu) - 1.0
    };
    let set_on = FIRST_FIT
        .iter()
        .chain(FIRST_HELD_OUT)
        .chain(DESIGNS[..18].iter().flat_map(|d| d.1.iter()));
    let largest = set_on.map(gain).fold(0.0, f64::max);
    let later = DOE19.iter().map(gain).fold(0.0, f64::max);
    println!("largest end-face gain, corner-filleted inside the ranges: {largest} (DOE19: {later})");
    assert!(largest <= END_FACE_VALIDATED_GAIN && END_FACE_VALIDATED_GAIN - largest < 1e-4);
}

/// Whether a reference lies inside the calibrated ranges: no range warning
/// (`hinge::calibration::range_warnings`) and, as the `hinge` analysis adds, no short-blank
/// warning (`short_blank_warning`).
fn in_range(spec: &HingeSpec) -> bool {
    use flexfem::hinge::calibration::{range_warnings, short_blank_warning};
    let profile = spec.profile().unwrap();
    range_warnings(&profile).is_empty() && short_blank_warning(&profile).is_none()
}

/// One family on the held-out designs ([`HELD_OUT`]), the references inside the calibrated
/// ranges ([`in_range`]): the fresh design (the last) against `fresh`; [`DOE3`] to [`DOE7`]
/// together and the later ones each (each compared once with the model of its day, seen by
/// later changes and, the corner-filleted rows, by the refits of the torsion law) against
/// `seen`. The references outside the ranges, which warn, against `beyond` (all designs
/// together). `counts`: the family's rows per design, and how many of them are outside the
/// ranges per design; `beyond` is `None` where none is.
fn held_out(
    name: &str,
    f: fn(&HingeSpec) -> bool,
    counts: ([usize; 17], [usize; 17]),
    fresh: [f64; 4],
    seen: [f64; 4],
    beyond: Option<[f64; 4]>,
) {
    let designs = HELD_OUT.map(|(_, d)| rows(&d.iter().collect::<Vec<_>>()));
    let all = designs.each_ref().map(|r| family(r, f));
    assert_eq!(all.each_ref().map(|r| r.len()), counts.0);
    // (inside the ranges, outside them) per design.
    let split = all.map(|r| r.into_iter().partition::<Vec<&Row>, _>(|r| in_range(&r.spec)));
    assert_eq!(
        split.each_ref().map(|(_, out)| out.len()),
        counts.1,
        "{name} outside the calibrated ranges, per design"
    );
    let outside: Vec<&Row> = split.iter().flat_map(|(_, out)| out.iter().copied()).collect();
    match beyond {
        Some(tol) => check(
            &format!("{name}, outside the calibrated ranges"),
            report(
                &format!("{name} vs CalculiX, HELD OUT, outside the calibrated ranges (warned)"),
                &outside,
            ),
            tol,
        ),
        None => assert!(outside.is_empty(), "{name}: references outside the ranges"),
    }
    let per_design = split.map(|(inside, _)| inside);
    let earlier: Vec<&Row> = per_design[..EARLIER].iter().flatten().copied().collect();
    let (first, last) = (HELD_OUT[0].0, HELD_OUT[EARLIER - 1].0);
    check(
        &format!("{name}, {first} to {last}"),
        report(
            &format!("{name} vs CalculiX, HELD OUT, seen by later changes, {first} to {last}"),
            &earlier,
        ),
        seen,
    );
    let n = HELD_OUT.len();
    // zip-checked: per_design is mapped from HELD_OUT (its type says 17).
    for ((design, _), rows) in HELD_OUT.iter().zip(&per_design).take(n - 1).skip(EARLIER) {
        check(
            &format!("{name}, {design}"),
            report(
                &format!("{name} vs CalculiX, HELD OUT, seen by later changes, {design}"),
                rows,
            ),
            seen,
        );
    }
    let design = HELD_OUT[n - 1].0;
    check(
        &format!("{name}, {design}"),
        report(&format!("{name} vs CalculiX, HELD OUT, {design}"), &per_design[n - 1]),
        fresh,
    );
}

#[test]
fn circular_notches_held_out() {
    held_out(
        "circular notches",
        circular,
        (
            [4, 12, 12, 12, 12, 18, 16, 6, 6, 6, 6, 6, 6, 6, 14, 12, 12],
            [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 5, 6, 6],
        ),
        CIRCULAR_TOL,
        CIRCULAR_SEEN_TOL,
        Some(CIRCULAR_BEYOND_TOL),
    );
}

#[test]
fn corner_filleted_held_out() {
    held_out(
        "corner-filleted hinges",
        corner,
        (
            [16, 12, 12, 12, 20, 20, 16, 24, 24, 24, 24, 24, 24, 24, 16, 20, 20],
            [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 16, 0, 14, 14],
        ),
        CORNER_TOL,
        CORNER_SEEN_TOL,
        Some(CORNER_BEYOND_TOL),
    );
}

/// The regimes where the model is known to read further from CalculiX than the targets
/// (`flexfem::hinge::calibration::known_bias`) and the band each warning states: over every
/// circular and corner-filleted reference of every design in a regime and inside the calibrated
/// ranges (where the regime's warning is the one shown), the stated band is the measured one
/// (lowest and highest error, to two decimals) and leaves the target, the stated model count is
/// the regime's, a quantity with no band stays within its target there, and every reference
/// outside the regimes is within [`OUTSIDE_BIAS_TOL`] (bending, torsion, axial, %). The
/// references outside the calibrated ranges, which get a range warning instead
/// (`range_warnings`, and the `hinge` analysis's `short_blank_warning`), are counted: the 16 of
/// [`DOE16`]'s leaves in tall very short or very tall blanks, [`DOE17`]'s 5, [`DOE18`]'s 20 and
/// [`DOE19`]'s 20 (checked in [`held_out`]), 61 in all; 430 others.
#[test]
fn known_bias_warnings_state_the_measured_bands() {
    use flexfem::hinge::calibration::{known_bias, SHORT_WIDE_LEAF};
    let refs: Vec<&CcxRef> = FIRST_FIT
        .iter()
        .chain(FIRST_HELD_OUT)
        .chain(DESIGNS.iter().flat_map(|d| d.1.iter()))
        .collect();
    let all = rows(&refs);
    let biases = [SHORT_WIDE_LEAF];
    // The errors of the rows in each regime, in the order of `biases`.
    let mut seen: [Vec<[f64; 4]>; 1] = Default::default();
    let mut outside = [0.0f64; 4];
    let (mut range_warned, mut others) = (0, 0);
    for row in all.iter().filter(|r| !neck(&r.spec)) {
        if !in_range(&row.spec) {
            range_warned += 1;
            continue;
        }
        let profile = row.spec.profile().unwrap();
        match known_bias(&profile) {
            Some(b) => seen[biases.iter().position(|x| x.regime == b.regime).unwrap()].push(row.err),
            None => {
                others += 1;
                // zip-checked: both hold the four quantities (their types say 4).
                for (worst, e) in outside.iter_mut().zip(row.err) {
                    *worst = worst.max(e.abs());
                }
            }
        }
    }
    // zip-checked: both arrays hold one entry per regime (their types say 1).
    for (bias, errs) in biases.iter().zip(&seen) {
        assert_eq!(errs.len(), bias.models, "{}", bias.regime);
        for q in 0..3 {
            let lo = errs.iter().map(|e| e[q]).fold(f64::INFINITY, f64::min);
            let hi = errs.iter().map(|e| e[q]).fold(f64::NEG_INFINITY, f64::max);
            println!(
                "{}: quantity {q}: {lo:+.2} … {hi:+.2} % over {} models",
                bias.regime,
                errs.len()
            );
            match bias.bands[q] {
                Some((b_lo, b_hi)) => {
                    // The stated band is the measured one (to its two decimals), and it leaves
                    // the target.
                    assert!(
                        (lo - b_lo).abs() < 0.006 && (hi - b_hi).abs() < 0.006,
                        "{}: measured {lo:.2} … {hi:.2}, stated {b_lo} … {b_hi}",
                        bias.regime
                    );
                    assert!(
                        b_lo < -TARGET[q] || b_hi > TARGET[q],
                        "{}: band within the target",
                        bias.regime
                    );
                }
                None => assert!(lo.abs().max(hi.abs()) < TARGET[q], "{}: {lo} … {hi}", bias.regime),
            }
        }
    }
    assert_eq!(range_warned, 61, "references outside the calibrated ranges");
    assert_eq!(others, 430, "references inside the ranges and outside the regimes");
    println!("outside the known-bias regimes: worst bending / torsion / axial / peak {outside:.2?} %");
    for q in 0..4 {
        assert!(
            outside[q] < OUTSIDE_BIAS_TOL[q],
            "outside the regimes: {:.2} %",
            outside[q]
        );
    }
}

/// Every CalculiX reference inside the calibrated ranges and outside the known-bias regimes
/// (bending, torsion, axial, peak stress, %; 406 references): measured 2.97 / 9.67 / 4.71 / 4.40
/// (4.71 % axial on [`DOE16`]'s circular R4.2/t0.4/w5.9, 4.40 % peak on [`DOE17`]'s circular
/// R1.4/t0.4/w2.2/h8.4; 2.97 / 9.67 / 4.15 on the 468 the axial law was fitted on)
/// since the axial load's spreading into the blank (2.97 / 9.67 /
/// 5.00 before it, the fifteenth design's l4.7/R1.0/t1.95/w17.9/h17.05/b9.45, w/l 3.8, reading
/// −4.999 % axially, now −2.08 %; 2.97 / 9.32 / 3.95 before the fifteenth design; torsion 9.09
/// before the fourteenth design) against the bending
/// reference's upper bound ([`eighth_bending`]): the targets (2.97 / 8.55 / 3.95 before [`DOE12`]; 8.68 % torsion with the slopes 1.3 and 1.11
/// of the eleventh design's comparison). Against the extrapolation alone, bending read −3.00 %
/// on [`DOE12`]'s l2.4/R0.6/t1.05/w8.9/h6.9, a short leaf in a tall blank just short of the
/// regime's width (w/l 3.7); −1.30 % against the bound. With the warping constant's first blank slope,
/// 0.84, torsion read 10.76 % on [`DOE10`]'s l3.25/R1.05/t1.35/w12.1/h9.8, a short leaf with
/// sharp fillets in a tall blank just short of the regime's width (w/l 3.7); the slope refitted
/// on ten designs (1.11) takes it to −8.68 %. (The regime's bounds were set on the earlier
/// designs and were not moved to take it in.)
const OUTSIDE_BIAS_TOL: [f64; 4] = [3.0, 10.0, 5.0, 5.0];

/// The turned necks (the Ruiz et al. neck and three others; the neck's model is the earlier
/// scikit-fem calibration, not refitted here).
#[test]
fn turned_necks() {
    let all = fit_rows();
    let rows = family(&all, neck);
    assert_eq!(rows.len(), 4);
    check("turned necks", report("turned necks vs CalculiX", &rows), NECK_TOL);
}

/// The rows the current torsion law was fitted on, with [`DOE2`] (its held-out check, seen
/// before the corner-filleted bending law was changed), against the same targets.
#[test]
fn rows_used_in_the_fits() {
    let all = fit_rows();
    let circ = family(&all, circular);
    let corn = family(&all, corner);
    assert_eq!((circ.len(), corn.len(), all.len()), (50, 44, 98));
    check(
        "fitted circular notches",
        report("circular notches vs CalculiX, FIT", &circ),
        CIRCULAR_FIT_TOL,
    );
    check(
        "fitted corner-filleted hinges",
        report("corner-filleted hinges vs CalculiX, FIT", &corn),
        CORNER_FIT_TOL,
    );
}

/// Which peak stress of the solid models is converged: the rows of
/// `tools/ccx_reference_convergence.jsonl` at n = 3, 4, 5 elements across the local thickness
/// (the Ruiz et al. notch R8/t2 and the corner-filleted l6/R2/t1.5 hinge). Measured, n = 4 → 5:
/// nodal-averaged peak +0.39 % / +0.63 %, integration-point peak +2.29 % / +1.24 %, stiffnesses
/// ≤ 0.21 % / ≤ 0.32 %; at n = 5 the integration-point peak lies 4.85 % / 6.82 % below the nodal
/// one.
#[test]
fn peak_stress_mesh_convergence() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tools/ccx_reference_convergence.jsonl"
    ))
    .unwrap();
    let lines: Vec<serde_json::Value> = text.lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    let at = |kind: &str, r: f64, n: f64, key: &str| -> f64 {
        let hits: Vec<f64> = lines
            .iter()
            .filter(|l| l["type"] == kind && l["R"].as_f64() == Some(r) && l["n"].as_f64() == Some(n))
            .map(|l| l[key].as_f64().unwrap())
            .collect();
        assert_eq!(hits.len(), 1, "{kind} R = {r}, n = {n}");
        hits[0]
    };
    for (kind, r, tol_nodal, tol_ip, gap) in CONV_TOL {
        let pct = |key: &str| 100.0 * (at(kind, r, 5.0, key) / at(kind, r, 4.0, key) - 1.0);
        let (nodal, ip) = (pct("stress_per_moment_nodal"), pct("stress_per_moment_ip"));
        let stiff = pct("k_bend")
            .abs()
            .max(pct("k_torsion").abs())
            .max(pct("k_axial").abs());
        println!(
            "{kind}: n = 4 → 5 nodal peak {nodal:+.2} %, integration-point peak {ip:+.2} %, stiffnesses ≤ {stiff:.2} %"
        );
        assert!(nodal.abs() < tol_nodal, "{kind}: nodal peak moved {nodal:+.2} %");
        assert!(ip.abs() < tol_ip, "{kind}: integration-point peak moved {ip:+.2} %");
        assert!(stiff < 0.5, "{kind}: stiffness moved {stiff:.2} %");
        assert!(
            nodal.abs() < ip.abs(),
            "{kind}: the nodal-averaged peak converges faster"
        );
        // The integration-point peak stays below the surface (nodal) peak (measured at n = 5).
        let below =
            100.0 * (1.0 - at(kind, r, 5.0, "stress_per_moment_ip") / at(kind, r, 5.0, "stress_per_moment_nodal"));
        assert!(
            (below - gap).abs() < 0.5,
            "{kind}: integration-point peak {below:.2} % below the nodal one"
        );
    }
}

/// The references' own discretisation error (`tools/ccx_refine.py`). Every CalculiX model was
/// solved at n = 3 as well as n = 4, and the stiffnesses compared are the order-2 Richardson
/// extrapolation of the pair ([`CcxRef::converged`]). Checked here on the data alone, no flexfem
/// number involved:
/// * n = 4 is not converged: up to +47.14 % stiff in bending against the n = 3/4 extrapolation
///   on [`DOE19`]'s circular R1.9/t0.75/w12.4/h11.9 and +39.98 % on [`DOE17`]'s
///   R2.15/t0.7/w12.1/h10.9 (their n = 3 meshes too coarse), +22.01 % on
///   the sixteenth design's very tall blanks, +5.82 % before them (the
///   earlier claim, "within about 0.3 %", came from two hinges);
/// * on the references re-solved at n = 6 (`tools/ccx_refine_n6_results.jsonl`: every one with
///   at most 30,000 unknowns at n = 4, then the short or wide corner-filleted leaves, the
///   seventeenth design's circular notches in tall short blanks, and every reference where n = 4
///   lies more than 5 % above the n = 3/4 extrapolation in bending) the n = 3/4 extrapolation
///   agrees with the n = 4/6 one within [`EXTRAPOLATION_TOL`], on the short or wide leaves
///   within [`SHORT_WIDE_EXTRAPOLATION_TOL`], and where n = 3 is too coarse within
///   [`COARSE_N3_EXTRAPOLATION_TOL`] (where they differ, the n = 3 mesh is the coarse one: the
///   tables take the n = 4/6 extrapolation wherever it exists, [`converged_stiffness`]);
/// * on the hinge that prompted it (l5.95/R1.45/t1.95/w10.15/h11.9, solved at n = 3, 4, 5, 6, 8)
///   the n = 3/4 extrapolation agrees with the n = 6/8 one within 0.6 % in bending (measured
///   85284 against 85745 N·mm/rad, −0.54 %);
/// * the nodal-averaged peak stress, compared unextrapolated at n = 4, moves by
///   [`PEAK_N4_TO_N6`] from n = 4 to n = 6 on the re-solved references: the peak-stress
///   comparisons carry that uncertainty.
#[test]
fn extrapolation_checked_on_finer_meshes() {
    let n3 = compared_lines("ccx_refine_n3_results.jsonl");
    let coarse = |source: &serde_json::Value, index: &serde_json::Value| {
        n3.iter()
            .find(|c| c["source"] == *source && c["index"] == *index)
            .expect("an n = 3 line")
    };
    // The n = 4 results, each source file read once; `n4(l)` is the n = 4 line that `l` re-solves.
    let mut sources = std::collections::HashMap::new();
    for l in &n3 {
        let file = l["source"].as_str().unwrap();
        sources.entry(file).or_insert_with(|| json_lines(file));
    }
    let n4 = |l: &serde_json::Value| &sources[l["source"].as_str().unwrap()][l["index"].as_u64().unwrap() as usize];
    let quantities = ["k_bend", "k_torsion", "k_axial"];
    let at = |l: &serde_json::Value, q: &str| l[q].as_f64().unwrap();
    // n = 4 against the n = 3/4 extrapolation, over every reference.
    let mut off = [0.0f64; 3];
    for c in &n3 {
        let fine = n4(c);
        for (q, name) in quantities.iter().enumerate() {
            let k = richardson(at(fine, name), at(c, name), 4.0, 3.0);
            off[q] = off[q].max(100.0 * (at(fine, name) / k - 1.0));
        }
    }
    println!("n = 4 above the n = 3/4 extrapolation by up to {off:.2?} % (bending, torsion, axial)");
    assert!(
        (47.0..47.3).contains(&off[0]),
        "bending: n = 4 off by up to {:.2} %",
        off[0]
    );
    // The n = 3/4 extrapolation against the n = 4/6 one: on the short or wide corner-filleted
    // leaves, and on the rest.
    let n6 = compared_lines(N6_RESULTS);
    let short_or_wide = |l: &serde_json::Value| {
        l["type"] == "corner_filleted" && (at(l, "l") / at(l, "t") <= 2.75 || at(l, "w") / at(l, "l") > 3.0)
    };
    // The others whose n = 3 mesh is too coarse: n = 4 more than 5 % from the n = 3/4
    // extrapolation in bending (re-solved at n = 6 for that reason, `tools/ccx_refine.py`).
    let coarse_n3 = |l4: &serde_json::Value, l3: &serde_json::Value| {
        (at(l4, "k_bend") / richardson(at(l4, "k_bend"), at(l3, "k_bend"), 4.0, 3.0) - 1.0).abs() > 0.05
    };
    // The rule holds: every such reference has its n = 6 line.
    for l3 in n3.iter().filter(|l3| coarse_n3(n4(l3), l3)) {
        assert!(
            n6.iter()
                .any(|l6| l6["source"] == l3["source"] && l6["index"] == l3["index"]),
            "{}: {}: n = 3 too coarse and no n = 6 line",
            l3["source"],
            l3["index"]
        );
    }
    // n = 4 not yet asymptotic (n = 4 → 6 beyond 5 % in bending): judged on n = 8 below.
    let pre_asymptotic_n4 =
        |l4: &serde_json::Value, l6: &serde_json::Value| (at(l4, "k_bend") / at(l6, "k_bend") - 1.0).abs() > 0.05;
    let (mut worst, mut peak) = ([[0.0f64; 3]; 4], (f64::INFINITY, f64::NEG_INFINITY));
    let mut counts = [0; 4];
    for l6 in &n6 {
        let (l4, l3) = (n4(l6), coarse(&l6["source"], &l6["index"]));
        let group = if pre_asymptotic_n4(l4, l6) {
            3
        } else if short_or_wide(l4) {
            1
        } else if coarse_n3(l4, l3) {
            2
        } else {
            0
        };
        counts[group] += 1;
        for (q, name) in quantities.iter().enumerate() {
            let k34 = richardson(at(l4, name), at(l3, name), 4.0, 3.0);
            let k46 = richardson(at(l6, name), at(l4, name), 6.0, 4.0);
            worst[group][q] = worst[group][q].max(100.0 * (k34 / k46 - 1.0).abs());
        }
        let moved = 100.0 * (at(l6, "stress_per_moment_nodal") / at(l4, "stress_per_moment_nodal") - 1.0);
        peak = (peak.0.min(moved), peak.1.max(moved));
    }
    println!(
        "{} references at n = 6 ({} short or wide corner-filleted, {} others with n = 3 too coarse, {} with n = 4 not yet asymptotic): n = 3/4 vs n = 4/6 extrapolation within {:.2?} % (short or wide: {:.2?} %; n = 3 too coarse: {:.2?} %); nodal peak n = 4 → 6 {:+.2} … {:+.2} %",
        n6.len(),
        counts[1],
        counts[2],
        counts[3],
        worst[0],
        worst[1],
        worst[2],
        peak.0,
        peak.1
    );
    assert_eq!(
        counts, N6_ROWS,
        "references re-solved at n = 6 (others, short or wide, n = 3 too coarse, n = 4 not asymptotic)"
    );
    for q in 0..3 {
        assert!(
            worst[0][q] < EXTRAPOLATION_TOL[q],
            "{}: {:.2} %",
            quantities[q],
            worst[0][q]
        );
        assert!(
            worst[1][q] < SHORT_WIDE_EXTRAPOLATION_TOL[q],
            "short or wide, {}: {:.2} %",
            quantities[q],
            worst[1][q]
        );
        assert!(
            worst[2][q] < COARSE_N3_EXTRAPOLATION_TOL[q],
            "n = 3 too coarse, {}: {:.2} %",
            quantities[q],
            worst[2][q]
        );
    }
    assert!(
        peak.0 > PEAK_N4_TO_N6.0 && peak.1 < PEAK_N4_TO_N6.1,
        "nodal peak n = 4 → 6: {:+.2} … {:+.2} %",
        peak.0,
        peak.1
    );
    // Where n = 4 and n = 6 differ by more than 5 % in bending, n = 4 is not in the asymptotic
    // range: such a reference has an n = 8 line ([`N8_RESULTS`]), and the tables take the
    // n = 6/8 extrapolation. Its n = 6 → 8 step is the asymptotic one again: the n = 4/6
    // extrapolation is then judged against the n = 6/8 one.
    let n8 = compared_lines(N8_RESULTS);
    let n10 = compared_lines(N10_RESULTS);
    let (mut pre_asymptotic, mut pre_asymptotic_n6) = (0, 0);
    for l6 in &n6 {
        let l4 = n4(l6);
        if !pre_asymptotic_n4(l4, l6) {
            continue;
        }
        pre_asymptotic += 1;
        let l8 = n8
            .iter()
            .find(|l| l["source"] == l6["source"] && l["index"] == l6["index"])
            .unwrap_or_else(|| {
                panic!(
                    "{}: {}: n = 4 → 6 beyond 5 % and no n = 8 line",
                    l6["source"], l6["index"]
                )
            });
        let k46 = richardson(at(l6, "k_bend"), at(l4, "k_bend"), 6.0, 4.0);
        let k68 = richardson(at(l8, "k_bend"), at(l6, "k_bend"), 8.0, 6.0);
        let steps = [
            100.0 * (at(l4, "k_bend") / at(l6, "k_bend") - 1.0),
            100.0 * (at(l6, "k_bend") / at(l8, "k_bend") - 1.0),
        ];
        println!(
            "{} {}: bending n = 4 → 6 {:+.2} %, n = 6 → 8 {:+.2} %; n = 4/6 extrapolation {:+.2} % from the n = 6/8 one",
            l6["source"],
            l6["index"],
            -steps[0],
            -steps[1],
            100.0 * (k46 / k68 - 1.0)
        );
        // Converged at n = 8, or still moving by more than 5 % (n = 6 not asymptotic either):
        // then re-solved at n = 10 ([`N10_RESULTS`]), where it has converged.
        let l10 = n10
            .iter()
            .find(|l| l["source"] == l6["source"] && l["index"] == l6["index"]);
        if steps[1].abs() > 5.0 {
            let l10 = l10.unwrap_or_else(|| {
                panic!(
                    "{}: {}: n = 6 → 8 beyond 5 % and no n = 10 line",
                    l6["source"], l6["index"]
                )
            });
            let step = 100.0 * (at(l8, "k_bend") / at(l10, "k_bend") - 1.0);
            println!("{} {}: bending n = 8 → 10 {:+.2} %", l6["source"], l6["index"], -step);
            assert!(
                step.abs() < PRE_ASYMPTOTIC_N6_TO_N8 && step.abs() < steps[1].abs() / 4.0,
                "n = 8 → 10 {step:.2} % after n = 6 → 8 {:.2} %",
                steps[1]
            );
            pre_asymptotic_n6 += 1;
        } else {
            assert!(
                l10.is_none(),
                "{}: {}: an n = 10 line, not needed",
                l6["source"],
                l6["index"]
            );
            assert!(
                steps[1].abs() < PRE_ASYMPTOTIC_N6_TO_N8 && steps[1].abs() < steps[0].abs() / 4.0,
                "n = 6 → 8 {:.2} % after n = 4 → 6 {:.2} %",
                steps[1],
                steps[0]
            );
        }
    }
    assert_eq!(
        pre_asymptotic,
        n8.len(),
        "every n = 8 line is of a pre-asymptotic reference"
    );
    assert_eq!(pre_asymptotic, PRE_ASYMPTOTIC_ROWS);
    assert_eq!(
        pre_asymptotic_n6,
        n10.len(),
        "every n = 10 line is of a reference whose n = 6 is not asymptotic"
    );
    assert_eq!(pre_asymptotic_n6, PRE_ASYMPTOTIC_N6_ROWS);
    // The prompting hinge at n = 6 and 8 (default blank size cap).
    let conv = json_lines("ccx_refine_convergence.jsonl");
    let fine = |n: f64| {
        let hits: Vec<&serde_json::Value> = conv
            .iter()
            .chain(&n6)
            .filter(|l| l["source"] == "ccx_heldout2_results.jsonl" && l["index"] == 14)
            .filter(|l| l["n"].as_f64() == Some(n) && l["hmax"].as_f64() == Some(11.9 / 3.0))
            .collect();
        assert_eq!(hits.len(), 1, "n = {n}");
        at(hits[0], "k_bend")
    };
    let l3 = coarse(&"ccx_heldout2_results.jsonl".into(), &14.into());
    let l4 = n4(l3);
    let k34 = richardson(at(l4, "k_bend"), at(l3, "k_bend"), 4.0, 3.0);
    let k68 = richardson(fine(8.0), fine(6.0), 8.0, 6.0);
    println!("l5.95/R1.45 hinge: bending n = 3/4 extrapolation {k34:.0}, n = 6/8 {k68:.0}");
    assert!((k34 / k68 - 1.0).abs() < 0.006, "{k34} vs {k68}");
}

/// The converged peak stresses the tables compare with (`tools/ccx_peak_stress.py`,
/// [`PEAKS`]), checked on the data alone, no flexfem number involved. The full models of
/// `tools/ccx_reference.py` size the mesh by the local thickness (t/4 at n = 4), but at a small
/// fillet the radius sets the stress gradient: the l5/R0.5/t1/w1 hinge's nodal peak still rose
/// from n = 8 to 10. So each circular and corner-filleted reference was solved again for the
/// peak alone on its symmetric eighth (x, y, z ≥ 0: the stresses of a pure moment are symmetric
/// about x = 0 and y = 0 and antisymmetric about z = 0), with elements of min(ρ, t)/k at the
/// notch root growing at 0.4 away from it, k = 12. Checked here:
/// * every circular and corner-filleted reference has its converged peak, each at the notch root
///   (corner fillets: on the fillet arc within 30° of the flat's end; circular notches: within
///   ρ/4 of the waist), on the surface;
/// * k = 12 → 16 on the references re-solved at k = 16 ([`PEAKS_K16`]) moves the peak by less
///   than [`PEAK_K12_TO_K16`];
/// * the n = 4 peaks of the full models mostly lie below the converged ones: measured
///   −6.89 … +24.20 % (−3.80 … +9.26 % before [`DOE18`]; converged above n = 4 by 24.20 % on
///   [`DOE18`]'s circular R1.1/t0.35/w5.8/h7.2, whose n = 4 mesh is not yet asymptotic, by up
///   to 9.26 % otherwise, worst l4.5/R0.75/t1.5/w4.5, a corner-filleted FIT row; below it by
///   6.89 % on [`DOE18`]'s l4.45/R2.0/t1.2/w19.8/h19.1, a leaf in a very tall blank, by 3.80 %
///   on [`DOE17`]'s l2.9/R0.85/t1.05/w17.4/h6.45, −2.49 % before them), and the
///   small-fillet hinge's full-model peaks at n = 6, 8, 10 (7.335, 7.382, 7.449) approach its
///   converged 7.495 from below;
/// * the eighth's compliant-axis stiffness (2/θ, its rotation being half the whole hinge's
///   under a quarter of the moment) lies between the full model's converged (n = 3/4
///   extrapolated) bending and its n = 4 one, within [`EIGHTH_BEND_TOL`]: the check that the
///   symmetry conditions are those of the whole hinge (the eighth keeps n = 4 away from the
///   root, so it reads stiff like n = 4, a little less for its finer root).
#[test]
fn converged_peaks_checked() {
    let k12 = compared_lines(PEAKS);
    let at = |l: &serde_json::Value, q: &str| l[q].as_f64().unwrap();
    // One line per circular and corner-filleted reference of the results files.
    let mut sources = std::collections::HashMap::new();
    for l in &k12 {
        let file = l["source"].as_str().unwrap();
        sources.entry(file).or_insert_with(|| json_lines(file));
    }
    let flat_notches: usize = sources
        .values()
        .map(|lines| lines.iter().filter(|l| l["type"] != "spherical_neck").count())
        .sum();
    assert_eq!((sources.len(), k12.len(), flat_notches), (20, 592, 592));
    let (n3, n6) = (
        compared_lines("ccx_refine_n3_results.jsonl"),
        compared_lines(N6_RESULTS),
    );
    let (mut moved, mut bend) = ((f64::INFINITY, f64::NEG_INFINITY), (f64::INFINITY, f64::NEG_INFINITY));
    let mut on_flats = 0;
    for l in &k12 {
        let n4 = &sources[l["source"].as_str().unwrap()][l["index"].as_u64().unwrap() as usize];
        for key in ["type", "R", "t", "w", "h"] {
            assert_eq!(l[key], n4[key], "{key}");
        }
        let m = 100.0 * (at(l, "stress_per_moment_nodal") / at(n4, "stress_per_moment_nodal") - 1.0);
        moved = (moved.0.min(m), moved.1.max(m));
        let c3 = n3
            .iter()
            .find(|c| c["source"] == l["source"] && c["index"] == l["index"])
            .expect("an n = 3 line");
        // The converged bending as the tables take it (n = 4/6 where re-solved at n = 6).
        let c6 = n6
            .iter()
            .find(|c| c["source"] == l["source"] && c["index"] == l["index"]);
        let k = converged_value(at(n4, "k_bend"), at(c3, "k_bend"), c6.map(|c| at(c, "k_bend")));
        // Between the converged stiffness and the (stiff) n = 4 one of the full model.
        let below_n4 = 100.0 * (at(l, "k_bend") / at(n4, "k_bend") - 1.0);
        bend = (bend.0.min(100.0 * (at(l, "k_bend") / k - 1.0)), bend.1.max(below_n4));
        // Where the peak is: on the surface at the notch root.
        let [x, _, z] = [0, 1, 2].map(|i| l["peak_at"][i].as_f64().unwrap());
        let (r, t) = (at(l, "R"), at(l, "t"));
        if l["type"] == "corner_filleted" {
            let s = at(l, "l") / 2.0 - r;
            let on_flat = x <= s && (z - t / 2.0).abs() < 1e-3 * t;
            let angle = ((x - s) / r).asin().to_degrees();
            let on_arc = (0.0..30.0).contains(&angle) && ((x - s).hypot(t / 2.0 + r - z) - r).abs() < 1e-3 * r;
            assert!(on_flat || on_arc, "{l}");
            on_flats += usize::from(on_flat);
        } else {
            assert!(x < r / 4.0 && ((x).hypot(t / 2.0 + r - z) - r).abs() < 1e-3 * r, "{l}");
        }
    }
    println!("{on_flats} corner-filleted peaks on the flat, the others on the fillet arc");
    println!("n = 4 peak → converged {:+.2} … {:+.2} %; eighth's bending at least {:+.2} % from the full model's converged, at most {:+.2} % from its n = 4", moved.0, moved.1, bend.0, bend.1);
    // +31.03 % on [`DOE19`]'s unconverged notch (its k = 12 eighth is converged; its full
    // models are not), +24.20 % on [`DOE18`]'s R1.1/t0.35 notch.
    assert!(moved.0 > -7.0 && moved.1 < 31.1, "n = 4 → converged {moved:?}");
    assert!(bend.0 > -EIGHTH_BEND_TOL && bend.1 < 0.0, "eighth's bending {bend:?}");
    // Refinement k = 12 → 16.
    let k16 = json_lines(PEAKS_K16);
    let mut worst: f64 = 0.0;
    for l in &k16 {
        let c = k12
            .iter()
            .find(|c| c["source"] == l["source"] && c["index"] == l["index"])
            .unwrap();
        worst = worst.max(100.0 * (at(l, "stress_per_moment_nodal") / at(c, "stress_per_moment_nodal") - 1.0).abs());
    }
    println!("{} references at k = 16: peak within {worst:.2} % of k = 12", k16.len());
    assert!(k16.len() >= PEAKS_K16_ROWS, "{} rows at k = 16", k16.len());
    assert!(worst < PEAK_K12_TO_K16, "k = 12 → 16: {worst:.2} %");
    // The turned necks keep their n = 4 peak: how far n = 6 moves it.
    let mut neck_moved: f64 = 0.0;
    let mut necks = 0;
    for l6 in n6.iter().filter(|l| l["type"] == "spherical_neck") {
        let n4 = &sources[l6["source"].as_str().unwrap()][l6["index"].as_u64().unwrap() as usize];
        neck_moved =
            neck_moved.max(100.0 * (at(l6, "stress_per_moment_nodal") / at(n4, "stress_per_moment_nodal") - 1.0).abs());
        necks += 1;
    }
    println!("turned necks ({necks}): nodal peak n = 4 → 6 within {neck_moved:.2} %");
    assert!(
        necks == 4 && neck_moved < NECK_PEAK_N4_TO_N6,
        "{necks} necks, {neck_moved:.2} %"
    );
    // The small fillet, approached from below by the full models.
    let small = k12
        .iter()
        .find(|l| l["source"] == "ccx_reference_results.jsonl" && l["index"] == 35)
        .unwrap();
    assert_eq!((at(small, "R"), at(small, "t"), at(small, "w")), (0.5, 1.0, 1.0));
    let full: Vec<f64> = json_lines("ccx_refine_convergence.jsonl")
        .iter()
        .filter(|l| l["R"] == 0.5)
        .map(|l| at(l, "stress_per_moment_nodal"))
        .collect();
    assert!(
        full.len() == 2 && full.iter().all(|&p| p < at(small, "stress_per_moment_nodal")),
        "{full:?}"
    );
}
