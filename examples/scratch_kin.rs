use flexfem::kinematics::*;
fn main() {
    let prs = Prs::new(109.215, 47.91, 45f64.to_radians(), 0.0).unwrap();
    for s in [[1.395, 1.531, 1.306], [0.777, 0.685, 0.725], [-0.676, -0.494, -0.706], [-1.485, -1.175, -1.781]] {
        let f = prs.fkp(s, None).unwrap();
        let p = f.pose;
        println!("{:?} z={:.1}um psi={:.2}\" th={:.2}\" it={}", s, p.z*1000.0, p.psi.to_degrees()*3600.0, p.theta.to_degrees()*3600.0, f.iterations);
    }
    let r = workspace::sweep(&prs, &PoseBox{z:[-2.0,2.0], psi:[-0.2f64.to_radians(),0.2f64.to_radians()], theta:[-0.2f64.to_radians(),0.2f64.to_radians()], steps:9}).unwrap();
    let d = |v:[f64;2]| [v[0].to_degrees(), v[1].to_degrees()];
    println!("s {:?} rev {:?} m {:?} n {:?} l {:?}", r.s, d(r.revolute_delta), d(r.spherical_m), d(r.spherical_n), d(r.spherical_l));
}
