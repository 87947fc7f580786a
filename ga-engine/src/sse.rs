//! One `f32` body's quaternion, and its world momentum and torque, each in one SSE
//! register, for the one-body step on x86-64.
//!
//! The one-body step is bound by its chain of three dependent turns, and by how many
//! bodies' instructions the core can hold at once to overlap one body's chain with the
//! next one's. Written in components, each turn's quaternion product is twelve scalar
//! operations, and LLVM's SLP vectoriser packs them, with the turns' scalar chain, into
//! vectors with shuffles (BENCHMARKS.md, issue 19). Here the quaternion is one register
//! from the start, and a turn `q (c + s e_K)` is `q c + perm_K(q) (±s)`: one shuffle for
//! the permutation, two broadcasts, a sign flip, two products and a sum. The angles,
//! norms and body momentum stay scalar, as in the component form. The world momentum
//! `[x, y, z, 0]` is one register too ([`V4`]): the kicks, `|L|^2` and the turn into the
//! body frame read it without assembling it from components. The turn about `L` is a
//! left product `w q`: four products of broadcast, pre-signed `w` lanes (`k L` in one
//! product, known from the step's start) with three shuffles of `q`.
//!
//! Every lane does the IEEE operations the component form does, on the same operands:
//! `w c - x s` is `w c + (-x) s`, exactly (negation is exact, and `+` and `*` commute
//! bit for bit). So the bits are those of `splitting::step2` on components, which the
//! slice form and other targets run; a unit test in `splitting.rs` compares them.

use core::arch::x86_64::{
    __m128, _mm_add_ps, _mm_add_ss, _mm_cvtss_f32, _mm_div_ps, _mm_movehl_ps, _mm_movelh_ps,
    _mm_mul_ps, _mm_set1_ps, _mm_set_ss, _mm_setr_ps, _mm_shuffle_ps, _mm_storeu_ps, _mm_sub_ps,
    _mm_unpackhi_ps, _mm_unpacklo_ps, _mm_xor_ps,
};

use super::real::Real;
use super::rotation::{Q, V};
use super::turning::{Momentum, Turning};

/// A quaternion `[x, y, z, w]`, lane 0 first (glam's `Quat` layout).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct Q4(__m128);

/// The lanes `q (c + s e_K)` takes `s` times, and with which sign, as `Q::turn_about`
/// writes them: `K = 0`: `x += w s, y += z s, z -= y s, w -= x s`.
macro_rules! turn_lanes {
    ($q:expr, $c:expr, $s:expr, $perm:expr, [$sx:expr, $sy:expr, $sz:expr, $sw:expr]) => {{
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let permuted = _mm_shuffle_ps::<$perm>($q, $q);
            let signs = _mm_setr_ps($sx, $sy, $sz, $sw);
            let s = _mm_xor_ps(_mm_set1_ps($s), signs);
            _mm_add_ps(_mm_mul_ps($q, _mm_set1_ps($c)), _mm_mul_ps(permuted, s))
        }
    }};
}

impl Turning<f32> for Q4 {
    #[inline(always)]
    fn pack(q: Q<f32>) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        Q4(unsafe { _mm_setr_ps(q.x, q.y, q.z, q.w) })
    }

    #[inline(always)]
    fn unpack(self) -> Q<f32> {
        let mut out = [0.0f32; 4];
        // SAFETY: SSE2 is part of x86-64; `out` holds four floats.
        unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
        Q {
            x: out[0],
            y: out[1],
            z: out[2],
            w: out[3],
        }
    }

    #[inline(always)]
    fn turned_about<const K: usize>(self, c: f32, s: f32) -> Self {
        // Lane i of the permutation is the component lane i takes `s` times; `-0.0`
        // flips the sign of `s` in that lane.
        Q4(match K {
            // x: w, y: z, z: -y, w: -x
            0 => turn_lanes!(self.0, c, s, 0b00_01_10_11, [0.0, 0.0, -0.0, -0.0]),
            // x: -z, y: w, z: x, w: -y
            1 => turn_lanes!(self.0, c, s, 0b01_00_11_10, [-0.0, 0.0, 0.0, -0.0]),
            // x: y, y: -x, z: w, w: -z
            _ => turn_lanes!(self.0, c, s, 0b10_11_00_01, [0.0, -0.0, 0.0, -0.0]),
        })
    }

    #[inline(always)]
    fn normalized_by(self, norm2: f32, reference: Self) -> Self {
        let norm = Real::sqrt(norm2);
        let k = if self.dot(reference) < 0.0 {
            -norm
        } else {
            norm
        };
        // SAFETY: SSE2 is part of x86-64.
        Q4(unsafe { _mm_div_ps(self.0, _mm_set1_ps(k)) })
    }

    #[inline(always)]
    fn times(self, b: Q<f32>) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        self.times_lanes(unsafe { _mm_setr_ps(b.x, b.y, b.z, b.w) })
    }

    #[inline(always)]
    fn times_conj(self, b: Q<f32>) -> Self {
        // `b*` from `b`'s four lanes by one sign flip (exact), not component by component.
        // SAFETY: SSE2 is part of x86-64.
        self.times_lanes(unsafe {
            _mm_xor_ps(
                _mm_setr_ps(b.x, b.y, b.z, b.w),
                _mm_setr_ps(-0.0, -0.0, -0.0, 0.0),
            )
        })
    }

    #[inline(always)]
    fn divided_by_norm(self, norm2: f32) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        Q4(unsafe { _mm_div_ps(self.0, _mm_set1_ps(Real::sqrt(norm2))) })
    }

    type Momentum = V4;

    #[inline(always)]
    fn turned_about_momentum(self, p: f32, k: f32, l: V4) -> Self {
        // `Q::mul(w, self)` for `w = (k l, p)`, lane by lane: each lane is `(w_w b0 +
        // w_x b1) + (w_y b2 + w_z b3)` with the component form's pairs (a difference
        // there is a sum of a negated product here, the same IEEE result). The `w` lanes
        // are known early; only the three shuffles of `self` wait for the turns.
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let b = self.0;
            // `k l` in one product, then each component broadcast with its signs from
            // the pairs `(w_i, -w_i)`.
            let kl = _mm_mul_ps(_mm_set1_ps(k), l.0);
            let negated = _mm_xor_ps(kl, _mm_set1_ps(-0.0));
            let xy = _mm_unpacklo_ps(kl, negated);
            let zw = _mm_unpackhi_ps(kl, negated);
            let aw = _mm_set1_ps(p);
            // (w_x, -w_x, w_x, -w_x), (w_y, w_y, -w_y, -w_y), (-w_z, w_z, w_z, -w_z).
            let ax = _mm_shuffle_ps::<0b01_00_01_00>(xy, xy);
            let ay = _mm_shuffle_ps::<0b11_11_10_10>(xy, xy);
            let az = _mm_shuffle_ps::<0b01_00_00_01>(zw, zw);
            let b1 = _mm_shuffle_ps::<0b00_01_10_11>(b, b);
            let b2 = _mm_shuffle_ps::<0b01_00_11_10>(b, b);
            let b3 = _mm_shuffle_ps::<0b10_11_00_01>(b, b);
            Q4(_mm_add_ps(
                _mm_add_ps(_mm_mul_ps(aw, b), _mm_mul_ps(ax, b1)),
                _mm_add_ps(_mm_mul_ps(ay, b2), _mm_mul_ps(az, b3)),
            ))
        }
    }

    #[inline(always)]
    fn rotate_inv(self, v: V4) -> V<f32> {
        // `Q::rotate` for `q*`: u = -(x, y, z); t = (2u) x v; (v + w t) + u x t, lane by
        // lane in the component form's order. Lane 3 carries nothing of use.
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let u = _mm_xor_ps(self.0, _mm_setr_ps(-0.0, -0.0, -0.0, 0.0));
            let w = _mm_shuffle_ps::<0b11_11_11_11>(self.0, self.0);
            let v4 = v.0;
            let t = cross(_mm_add_ps(u, u), v4);
            let r = _mm_add_ps(_mm_add_ps(v4, _mm_mul_ps(w, t)), cross(u, t));
            V {
                x: _mm_cvtss_f32(r),
                y: _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(r, r)),
                z: _mm_cvtss_f32(_mm_movehl_ps(r, r)),
            }
        }
    }

    #[inline(always)]
    fn select(mask: bool, yes: Self, no: Self) -> Self {
        if mask {
            yes
        } else {
            no
        }
    }

    #[inline(always)]
    fn dot(self, b: Self) -> f32 {
        // (x x' + y y') + (z z' + w w'), the component form's tree.
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let products = _mm_mul_ps(self.0, b.0);
            let pairs = _mm_add_ps(
                products,
                _mm_shuffle_ps::<0b10_11_00_01>(products, products),
            );
            _mm_cvtss_f32(_mm_add_ss(pairs, _mm_movehl_ps(pairs, pairs)))
        }
    }
}

impl Q4 {
    /// `self b` for `b` in lanes `[x, y, z, w]`, as `Q::mul`.
    #[inline(always)]
    fn times_lanes(self, b4: __m128) -> Self {
        // `Q::mul(self, b)` lane by lane: `(a_w B_w + a_x B_x) + (a_y B_y + a_z B_z)`
        // with `a`'s components broadcast (the only operations on the chain are the four
        // shuffles) and `B_k` the lanes of `b` each takes, signed, known beforehand.
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let a = self.0;
            let signed = |lanes: __m128, signs: __m128| _mm_xor_ps(lanes, signs);
            // B_x = (b_w, -b_z, b_y, -b_x), B_y = (b_z, b_w, -b_x, -b_y),
            // B_z = (-b_y, b_x, b_w, -b_z).
            let bx = signed(
                _mm_shuffle_ps::<0b00_01_10_11>(b4, b4),
                _mm_setr_ps(0.0, -0.0, 0.0, -0.0),
            );
            let by = signed(
                _mm_shuffle_ps::<0b01_00_11_10>(b4, b4),
                _mm_setr_ps(0.0, 0.0, -0.0, -0.0),
            );
            let bz = signed(
                _mm_shuffle_ps::<0b10_11_00_01>(b4, b4),
                _mm_setr_ps(-0.0, 0.0, 0.0, -0.0),
            );
            let aw = _mm_shuffle_ps::<0b11_11_11_11>(a, a);
            let ax = _mm_shuffle_ps::<0b00_00_00_00>(a, a);
            let ay = _mm_shuffle_ps::<0b01_01_01_01>(a, a);
            let az = _mm_shuffle_ps::<0b10_10_10_10>(a, a);
            Q4(_mm_add_ps(
                _mm_add_ps(_mm_mul_ps(aw, b4), _mm_mul_ps(ax, bx)),
                _mm_add_ps(_mm_mul_ps(ay, by), _mm_mul_ps(az, bz)),
            ))
        }
    }
}

/// A vector `[x, y, z, 0]`, lane 0 first (lane 3 unused): the world momentum and torque
/// of one body.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub(crate) struct V4(__m128);

impl Momentum<f32> for V4 {
    #[inline(always)]
    fn pack(v: V<f32>) -> Self {
        // `(x, y)` as one pair and `z` alone, joined in one shuffle: LLVM loads the
        // pair with one instruction (from `_mm_setr_ps(x, y, z, z)` it loaded `x` alone
        // and `(y, z)`, and joined them with two shuffles).
        // SAFETY: SSE2 is part of x86-64.
        V4(unsafe {
            _mm_movelh_ps(
                _mm_unpacklo_ps(_mm_set_ss(v.x), _mm_set_ss(v.y)),
                _mm_set_ss(v.z),
            )
        })
    }

    #[inline(always)]
    fn unpack(self) -> V<f32> {
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            V {
                x: _mm_cvtss_f32(self.0),
                y: _mm_cvtss_f32(_mm_shuffle_ps::<0b01_01_01_01>(self.0, self.0)),
                z: _mm_cvtss_f32(_mm_movehl_ps(self.0, self.0)),
            }
        }
    }

    #[inline(always)]
    fn add_scaled(self, s: f32, t: Self) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        V4(unsafe { _mm_add_ps(self.0, _mm_mul_ps(_mm_set1_ps(s), t.0)) })
    }

    #[inline(always)]
    fn norm2(self) -> f32 {
        // `(x x + y y) + z z`, `V::dot`'s sums in its order.
        // SAFETY: SSE2 is part of x86-64.
        unsafe {
            let products = _mm_mul_ps(self.0, self.0);
            let xy = _mm_add_ss(
                products,
                _mm_shuffle_ps::<0b01_01_01_01>(products, products),
            );
            _mm_cvtss_f32(_mm_add_ss(xy, _mm_movehl_ps(products, products)))
        }
    }

    #[inline(always)]
    fn scaled(self, s: f32) -> Self {
        // SAFETY: SSE2 is part of x86-64.
        V4(unsafe { _mm_mul_ps(_mm_set1_ps(s), self.0) })
    }
}

/// `a x b` in lanes 0 to 2: `(a b.yzx - a.yzx b).yzx`, which is `a.yzx b.zxy - a.zxy
/// b.yzx` lane by lane (the same products, subtracted in the same order), as `V::cross`
/// writes each component, with three shuffles instead of four.
#[inline(always)]
unsafe fn cross(a: __m128, b: __m128) -> __m128 {
    let a_yzx = _mm_shuffle_ps::<0b11_00_10_01>(a, a);
    let b_yzx = _mm_shuffle_ps::<0b11_00_10_01>(b, b);
    let c = _mm_sub_ps(_mm_mul_ps(a, b_yzx), _mm_mul_ps(a_yzx, b));
    _mm_shuffle_ps::<0b11_00_10_01>(c, c)
}
