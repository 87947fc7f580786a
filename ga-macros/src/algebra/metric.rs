use super::blade::{grade, Blade};

/// The squares of the generators e1..en: each 1, -1 or 0.
#[derive(Clone, Debug)]
pub struct Metric {
    squares: Vec<i8>,
}

/// The bilinear products of the algebra. Each is a filter on the geometric product's
/// terms (Lichtso's model): one sign table, many products.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ProductKind {
    /// `a * b`.
    Geometric,
    /// `a ^ b`: keeps grade r + s.
    Outer,
    /// `a | b`, the lecture's inner product: keeps grade |r - s|.
    Inner,
    /// Keeps grade s - r, zero where r > s.
    LeftContraction,
    /// Keeps grade r - s, zero where s > r.
    RightContraction,
    /// Keeps grade 0.
    Scalar,
    /// (ab - ba) / 2: keeps the terms whose blades anticommute.
    Commutator,
    /// The regressive product (join), `undual(dual(a) ^ dual(b))` through the right
    /// complement: metric-free, so it works for degenerate metrics.
    Regressive,
}

impl ProductKind {
    /// Every product, in the order they are emitted.
    pub const ALL: [ProductKind; 8] = [
        ProductKind::Geometric,
        ProductKind::Outer,
        ProductKind::Inner,
        ProductKind::LeftContraction,
        ProductKind::RightContraction,
        ProductKind::Scalar,
        ProductKind::Commutator,
        ProductKind::Regressive,
    ];

    /// The name used in ops lists and in `TERM_COUNTS`.
    pub fn name(self) -> &'static str {
        match self {
            ProductKind::Geometric => "geometric",
            ProductKind::Outer => "outer",
            ProductKind::Inner => "inner",
            ProductKind::LeftContraction => "left_contraction",
            ProductKind::RightContraction => "right_contraction",
            ProductKind::Scalar => "scalar_product",
            ProductKind::Commutator => "commutator",
            ProductKind::Regressive => "regressive",
        }
    }
}

/// The grade-sign rules that map each blade to plus or minus itself.
#[allow(clippy::enum_variant_names)] // `GradeInvolution` is the name of the operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Involution {
    /// Leaves every blade alone.
    Identity,
    /// ~A: flips grades 2 and 3 mod 4.
    Reverse,
    /// Flips odd grades.
    GradeInvolution,
    /// Reverse composed with grade involution: flips grades 1 and 2 mod 4.
    Conjugate,
}

impl Involution {
    /// The sign this involution puts on a blade.
    pub fn sign(self, blade: Blade) -> i8 {
        let k = grade(blade);
        let reverse = if (k / 2).is_multiple_of(2) { 1 } else { -1 };
        let parity = if k.is_multiple_of(2) { 1 } else { -1 };
        match self {
            Involution::Identity => 1,
            Involution::Reverse => reverse,
            Involution::GradeInvolution => parity,
            Involution::Conjugate => reverse * parity,
        }
    }
}

/// The sign of moving the generators of `b` past those of `a` into ascending order,
/// ignoring the metric: the parity of the number of swaps.
pub fn reorder_sign(a: Blade, b: Blade) -> i8 {
    let mut swaps = 0;
    let mut rest = a >> 1;
    while rest != 0 {
        swaps += (rest & b).count_ones();
        rest >>= 1;
    }
    if swaps % 2 == 0 {
        1
    } else {
        -1
    }
}

impl Metric {
    /// A metric from the generators' squares, already validated to be 1, -1 or 0.
    pub fn new(squares: Vec<i8>) -> Self {
        Metric { squares }
    }

    /// The null generator of a projective (plane-based) algebra: the one generator that
    /// squares to 0 when all the others square to 1, as in 3D PGA's `[0, 1, 1, 1]`.
    pub fn projective_origin(&self) -> Option<usize> {
        let nulls: Vec<usize> = (0..self.squares.len())
            .filter(|&i| self.squares[i] == 0)
            .collect();
        let euclidean = self.squares.iter().filter(|&&q| q == 1).count();
        (nulls.len() == 1 && euclidean + 1 == self.squares.len() && euclidean >= 2)
            .then(|| nulls[0])
    }

    /// The number of generators.
    pub fn dimension(&self) -> usize {
        self.squares.len()
    }

    /// The pseudoscalar e1..en.
    pub fn pseudoscalar(&self) -> Blade {
        (1 << self.dimension()) - 1
    }

    /// The square of the pseudoscalar: 1, -1 or 0.
    pub fn pseudoscalar_square(&self) -> i8 {
        let i = self.pseudoscalar();
        self.geometric(i, i).0
    }

    /// The geometric product of two blades: a sign (0 when a shared generator squares
    /// to 0) and the resulting blade.
    pub fn geometric(&self, a: Blade, b: Blade) -> (i8, Blade) {
        let mut sign = reorder_sign(a, b);
        let shared = a & b;
        for (i, &square) in self.squares.iter().enumerate() {
            if shared & (1 << i) != 0 {
                sign *= square;
            }
        }
        (sign, a ^ b)
    }

    /// The coefficient (-1, 0 or 1) with which `a` times `b` contributes to blade `a ^ b`
    /// under the given product.
    pub fn product(&self, kind: ProductKind, a: Blade, b: Blade) -> (i8, Blade) {
        if kind == ProductKind::Regressive {
            return self.regressive(a, b);
        }
        let (sign, out) = self.geometric(a, b);
        let (r, s, t) = (grade(a) as i32, grade(b) as i32, grade(out) as i32);
        let keep = match kind {
            ProductKind::Geometric => true,
            ProductKind::Outer => t == r + s,
            ProductKind::Inner => t == (r - s).abs(),
            ProductKind::LeftContraction => s >= r && t == s - r,
            ProductKind::RightContraction => r >= s && t == r - s,
            ProductKind::Scalar => t == 0,
            ProductKind::Commutator => self.geometric(b, a).0 == -sign,
            ProductKind::Regressive => unreachable!("answered above"),
        };
        (if keep { sign } else { 0 }, out)
    }

    /// The right complement of a blade: the sign and blade C with `a ^ C = e1..en`.
    pub fn dual(&self, a: Blade) -> (i8, Blade) {
        let complement = self.pseudoscalar() ^ a;
        (reorder_sign(a, complement), complement)
    }

    /// The regressive product of two blades, `undual(dual(a) ^ dual(b))`: zero unless
    /// the complements share no generator (together `a` and `b` span the whole space).
    /// The dual and the outer product never read the squares, so neither does this.
    pub fn regressive(&self, a: Blade, b: Blade) -> (i8, Blade) {
        let (sa, ca) = self.dual(a);
        let (sb, cb) = self.dual(b);
        if ca & cb != 0 {
            return (0, 0);
        }
        let (su, out) = self.undual(ca | cb);
        (sa * sb * reorder_sign(ca, cb) * su, out)
    }

    /// The inverse of [`Metric::dual`].
    pub fn undual(&self, c: Blade) -> (i8, Blade) {
        let a = self.pseudoscalar() ^ c;
        (reorder_sign(a, c), a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::canonical_blades;

    fn g3() -> Metric {
        Metric::new(vec![1, 1, 1])
    }

    #[test]
    fn e1_e2_e1_is_minus_e2() {
        let m = g3();
        let (s1, b) = m.geometric(0b001, 0b010);
        let (s2, c) = m.geometric(b, 0b001);
        assert_eq!((s1 * s2, c), (-1, 0b010));
    }

    #[test]
    fn euclidean_bivectors_and_pseudoscalar_square_to_minus_one() {
        let m = g3();
        assert_eq!(m.geometric(0b011, 0b011), (-1, 0));
        assert_eq!(m.geometric(0b111, 0b111), (-1, 0));
        assert_eq!(m.pseudoscalar_square(), -1);
        assert_eq!(Metric::new(vec![1, 1, 1, 1]).pseudoscalar_square(), 1);
        assert_eq!(Metric::new(vec![1, 1, 1, 0]).pseudoscalar_square(), 0);
    }

    #[test]
    fn geometric_product_is_associative_on_blades_for_every_metric() {
        for squares in [
            vec![1, 1, 1, 1],
            vec![1, -1, -1, -1],
            vec![1, 1, 1, 0],
            vec![1, 1, 1, 1, -1],
        ] {
            let m = Metric::new(squares);
            let blades = canonical_blades(m.dimension());
            for &a in &blades {
                for &b in &blades {
                    for &c in &blades {
                        let (s1, ab) = m.geometric(a, b);
                        let (s2, abc) = m.geometric(ab, c);
                        let (s3, bc) = m.geometric(b, c);
                        let (s4, abc2) = m.geometric(a, bc);
                        assert_eq!((s1 * s2, abc), (s3 * s4, abc2));
                    }
                }
            }
        }
    }

    #[test]
    fn dual_then_undual_is_identity_and_wedges_to_the_pseudoscalar() {
        let m = Metric::new(vec![1, 1, 1, 0, 1, -1]);
        for a in canonical_blades(6) {
            let (s, c) = m.dual(a);
            let (t, back) = m.undual(c);
            assert_eq!((s * t, back), (1, a));
            assert_eq!(reorder_sign(a, c) * s, 1);
        }
    }

    #[test]
    fn product_filters_pick_their_grades() {
        let m = g3();
        assert_eq!(m.product(ProductKind::Outer, 0b001, 0b010), (1, 0b011));
        assert_eq!(m.product(ProductKind::Outer, 0b001, 0b001).0, 0);
        assert_eq!(
            m.product(ProductKind::LeftContraction, 0b001, 0b011),
            (1, 0b010)
        );
        assert_eq!(m.product(ProductKind::LeftContraction, 0b011, 0b001).0, 0);
        assert_eq!(
            m.product(ProductKind::RightContraction, 0b011, 0b001),
            (-1, 0b010)
        );
        assert_eq!(m.product(ProductKind::Inner, 0b011, 0b001), (-1, 0b010));
        assert_eq!(
            m.product(ProductKind::Commutator, 0b011, 0b101),
            (-1, 0b110)
        );
        assert_eq!(m.product(ProductKind::Commutator, 0b011, 0b100).0, 0);
    }

    #[test]
    fn regressive_meets_planes_in_lines_and_ignores_the_metric() {
        // In G3 the join of two blades is the meet of the subspaces they span: e12 v e23
        // is their common line e2, up to the complement's sign; e1 v e2 (lines through
        // the origin of a 3D space of vectors) is zero, and I v A = A.
        for squares in [vec![1, 1, 1], vec![0, 1, 1], vec![1, -1, 0]] {
            let m = Metric::new(squares);
            assert_eq!(m.product(ProductKind::Regressive, 0b011, 0b110), (1, 0b010));
            assert_eq!(
                m.product(ProductKind::Regressive, 0b110, 0b011),
                (-1, 0b010)
            );
            assert_eq!(m.product(ProductKind::Regressive, 0b001, 0b010).0, 0);
            for a in canonical_blades(3) {
                assert_eq!(m.product(ProductKind::Regressive, 0b111, a), (1, a));
            }
        }
    }
}
