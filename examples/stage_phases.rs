use flexfem::case::{self, Case};
use std::time::Instant;
fn main() {
    let text = include_str!("../cases/ruiz2019_stage.json");
    let Case::Stage(c) = case::parse(text).unwrap() else {
        panic!()
    };
    let (v, mut drives) = c.validated().unwrap();
    drives.truncate(1);
    let d = v.design().clone();
    let n = 2000;
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(d.validate().unwrap());
    }
    println!("validate {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(v.build());
    }
    println!("build {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let s = v.build();
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(s.solve(&drives).unwrap());
    }
    println!("solve {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let mut cache = flexfem::fem::SolverCache::new();
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(s.solve_with(&mut cache, &drives).unwrap());
    }
    println!("solve cached {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
    let t = Instant::now();
    for _ in 0..n {
        std::hint::black_box(flexfem::analysis::stage::run_stage_with(&c, false, &mut cache).unwrap());
    }
    println!("run_stage cached {:.1} us", t.elapsed().as_secs_f64() * 1e6 / n as f64);
}
