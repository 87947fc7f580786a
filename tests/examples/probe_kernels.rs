use ga_core::f64::{g3, g4};
fn main() {
    for sc in [1e160, 1e300, 1e-160, 1e-300] {
        let v = g3::Vector::new(1.0 * sc, 2.0 * sc, -0.5 * sc);
        let inv = v.inverse();
        println!("vec {sc:e}: inv {:?} check {:?}", inv, inv.map(|i| (v * i)));
        let b = g3::Bivector::new(1.0 * sc, 2.0 * sc, -0.5 * sc);
        println!("biv inv check {:?}", b.inverse().map(|i| b * i));
        let e = g3::Even::new(0.3 * sc, 1.0 * sc, 2.0 * sc, -0.5 * sc);
        println!("even inv check {:?}", e.inverse().map(|i| e * i));
        println!("norm {:e} normalized {:?}", v.norm(), v.normalized());
        println!("exp {:?} norm {}", b.exp(), b.exp().norm());
        let b4 = g4::Bivector::new(sc, 0.0, 0.0, 0.0, 0.0, sc);
        println!("g4 iso exp norm {}", b4.exp().norm());
        println!(
            "g4 biv inverse {:?}",
            g4::Bivector::new(sc, 2.0 * sc, 0.0, 0.0, 0.0, 0.0).inverse()
        );
        println!("g4 is_blade e12+e34 {}", b4.is_blade());
    }
    for a in [1e12, 1e16] {
        let b4 = g4::Bivector::new(a, 0.0, 0.0, 0.0, 0.0, a);
        println!("g4 iso {a:e} |R|-1 = {:e}", b4.exp().norm() - 1.0);
    }
    println!("{:?}", g3::Vector::new(1e-300, 0.0, 0.0).normalized());
    println!(
        "{:?}",
        g3::Vector::new(3e-160, 0.0, 0.0).normalized().norm()
    );
    println!("{:?}", g3::Vector::new(1e160, 0.0, 0.0).try_normalized());
    let i = g4::Even {
        e1234: 1.0,
        ..g4::Even::ZERO
    };
    println!(
        "log e1234 {:?} back {:?}",
        i.log(),
        i.log().map(|b| b.exp())
    );
    let i = g4::Even {
        e1234: -1.0,
        ..g4::Even::ZERO
    };
    println!(
        "log -e1234 {:?} back {:?}",
        i.log(),
        i.log().map(|b| b.exp())
    );
    println!(
        "log -1 g3 {:?}",
        (g3::Even::ONE * -1.0).log().map(|b| b.exp())
    );
    println!(
        "log -1 g4 {:?}",
        (g4::Even::ONE * -1.0).log().map(|b| b.exp())
    );
    println!("log 2 g3 {:?}", (g3::Even::ONE * 2.0).log());
    let r = g4::Bivector::new(0.3, -1.1, 0.5, 0.7, 0.2, -0.4).exp();
    println!("g4 log ok {:?}", r.log());
    let b = g4::Bivector::new(2.0, 0.0, 0.0, 0.0, 0.0, std::f64::consts::PI - 2.0);
    println!(
        "g4 boundary a+b=pi {:?} -> {:?} vs {:?}",
        b,
        b.exp().log().map(|x| x.exp()),
        b.exp()
    );
}
