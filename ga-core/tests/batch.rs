//! The structure-of-arrays batch types compute, lane by lane, exactly what the one-item
//! types compute: the same straight-line expressions on wider registers.

use ga_core::f32::g3 as s3;
use ga_core::f32::g4 as s4;
use ga_core::f64::g3 as d3;

use ga_test_rng::Rng;

#[test]
fn g3_f32_x4_and_x8_rotor_products_and_sandwiches_match_items_exactly() {
    let mut rng = Rng::new(3);
    for _ in 0..100 {
        let r: [s3::Rotor; 8] =
            std::array::from_fn(|_| s3::Rotor::from_array(rng.uniform_array_f32(-1.0, 1.0)));
        let q: [s3::Rotor; 8] =
            std::array::from_fn(|_| s3::Rotor::from_array(rng.uniform_array_f32(-1.0, 1.0)));
        let v: [s3::Vector; 8] =
            std::array::from_fn(|_| s3::Vector::from_array(rng.uniform_array_f32(-1.0, 1.0)));
        let products = (s3::x8::Rotor::from_items(r) * s3::x8::Rotor::from_items(q)).to_items();
        let rotated =
            s3::x8::Sandwich::sandwich(s3::x8::Rotor::from_items(r), s3::x8::Vector::from_items(v))
                .to_items();
        for i in 0..8 {
            assert_eq!(products[i], r[i] * q[i]);
            assert_eq!(rotated[i], s3::Sandwich::sandwich(r[i], v[i]));
        }
        let r4: [s3::Rotor; 4] = std::array::from_fn(|i| r[i]);
        let q4: [s3::Rotor; 4] = std::array::from_fn(|i| q[i]);
        let products4 = (s3::x4::Rotor::from_items(r4) * s3::x4::Rotor::from_items(q4)).to_items();
        for i in 0..4 {
            assert_eq!(products4[i], r[i] * q[i]);
        }
    }
}

#[test]
fn g4_f32_x4_full_products_match_items_exactly() {
    let mut rng = Rng::new(4);
    for _ in 0..100 {
        let a: [s4::Multivector; 4] =
            std::array::from_fn(|_| s4::Multivector::from_array(rng.uniform_array_f32(-1.0, 1.0)));
        let b: [s4::Multivector; 4] =
            std::array::from_fn(|_| s4::Multivector::from_array(rng.uniform_array_f32(-1.0, 1.0)));
        let products =
            (s4::x4::Multivector::from_items(a) * s4::x4::Multivector::from_items(b)).to_items();
        let wedges =
            (s4::x4::Multivector::from_items(a) ^ s4::x4::Multivector::from_items(b)).to_items();
        for i in 0..4 {
            assert_eq!(products[i], a[i] * b[i]);
            assert_eq!(wedges[i], a[i] ^ b[i]);
        }
    }
}

#[test]
fn g3_f64_x4_products_sums_and_reverses_match_items_exactly() {
    let mut rng = Rng::new(5);
    for _ in 0..100 {
        let a: [d3::Multivector; 4] =
            std::array::from_fn(|_| d3::Multivector::from_array(rng.uniform_array(-1.0, 1.0)));
        let b: [d3::Even; 4] =
            std::array::from_fn(|_| d3::Even::from_array(rng.uniform_array(-1.0, 1.0)));
        let (wa, wb) = (
            d3::x4::Multivector::from_items(a),
            d3::x4::Even::from_items(b),
        );
        let products = (wa * wb).to_items();
        let sums = (wa + wb).to_items();
        let reversed = wa.reverse().to_items();
        let splat = d3::x4::Even::splat(b[0]).to_items();
        for i in 0..4 {
            assert_eq!(products[i], a[i] * b[i]);
            assert_eq!(sums[i], a[i] + b[i]);
            assert_eq!(reversed[i], a[i].reverse());
            assert_eq!(splat[i], b[0]);
        }
    }
}
