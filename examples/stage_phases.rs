use flexfem::case::{self, Case};
use std::time::Instant;
fn main() {
    let mode = std::env::args().nth(1).unwrap_or_default();
    let n: usize = std::env::args().nth(2).map_or(2000, |s| s.parse().unwrap());
    let text = include_str!("../cases/ruiz2019_stage.json");
    let Case::Stage(c) = case::parse(text).unwrap() else {
        panic!()
    };
    let (v, mut drives) = c.validated().unwrap();
    drives.truncate(1);
    let d = v.design().clone();
    let s = v.build();
    let mut cache = flexfem::fem::SolverCache::new();
    let t = Instant::now();
    for _ in 0..n {
        match mode.as_str() {
            "validate" => {
                std::hint::black_box(d.validate().unwrap());
            }
            "solve" => {
                std::hint::black_box(s.solve(&drives).unwrap());
            }
            "cached" => {
                std::hint::black_box(s.solve_with(&mut cache, &drives).unwrap());
            }
            "bench" => {
                std::hint::black_box(d.build().unwrap().solve(&drives).unwrap());
            }
            "run" => {
                std::hint::black_box(flexfem::analysis::stage::run_stage_with(&c, false, &mut cache).unwrap());
            }
            _ => {}
        }
    }
    println!("{mode} {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
}
