//! A matrix on many vectors with AVX2 and FMA: the matrix's columns in one register each,
//! each vector's components broadcast from memory (a load, no shuffle), two fused
//! multiply-adds, and one store of a whole register. The store is one component wider than
//! a vector; it runs ahead into the next output slot, which the next iteration overwrites,
//! and the last vector is written by the scalar code.
#[cfg(feature = "f32")]
pub mod f32 {
    use crate::f32::g3::Vector;
    use core::arch::x86_64::{
        _mm_broadcast_ss, _mm_fmadd_ps, _mm_mul_ps, _mm_set_ps, _mm_storeu_ps,
    };

    /// `out[i] = m x[i]`.
    ///
    /// # Safety
    /// The CPU has AVX2 and FMA, and `x` and `out` have the same length.
    #[target_feature(enable = "avx2,fma")]
    pub unsafe fn apply_matrix(m: [[f32; 3]; 3], x: &[Vector], out: &mut [Vector]) {
        let Some(last) = x.len().checked_sub(1) else {
            return;
        };
        let column = |c: usize| _mm_set_ps(0.0, m[2][c], m[1][c], m[0][c]);
        let (c0, c1, c2) = (column(0), column(1), column(2));
        let output = out.as_mut_ptr().cast::<f32>();
        for (i, v) in x[..last].iter().enumerate() {
            let y = _mm_fmadd_ps(
                c2,
                _mm_broadcast_ss(&v.e3),
                _mm_fmadd_ps(
                    c1,
                    _mm_broadcast_ss(&v.e2),
                    _mm_mul_ps(c0, _mm_broadcast_ss(&v.e1)),
                ),
            );
            // SAFETY: `Vector` is `#[repr(C)]` of three `f32`, so slot `i` starts at
            // float `3 i`; the four floats written are slot `i` and the first
            // component of slot `i + 1`, which exists because `i < last`.
            unsafe { _mm_storeu_ps(output.add(3 * i), y) };
        }
        out[last] = crate::kernels::f32::apply(&m, &x[last]);
    }
}

#[cfg(feature = "f64")]
pub mod f64 {
    use crate::f64::g3::Vector;
    use core::arch::x86_64::{
        _mm256_broadcast_sd, _mm256_fmadd_pd, _mm256_mul_pd, _mm256_set_pd, _mm256_storeu_pd,
    };

    /// `out[i] = m x[i]`.
    ///
    /// # Safety
    /// The CPU has AVX2 and FMA, and `x` and `out` have the same length.
    #[target_feature(enable = "avx2,fma")]
    pub unsafe fn apply_matrix(m: [[f64; 3]; 3], x: &[Vector], out: &mut [Vector]) {
        let Some(last) = x.len().checked_sub(1) else {
            return;
        };
        let column = |c: usize| _mm256_set_pd(0.0, m[2][c], m[1][c], m[0][c]);
        let (c0, c1, c2) = (column(0), column(1), column(2));
        let output = out.as_mut_ptr().cast::<f64>();
        for (i, v) in x[..last].iter().enumerate() {
            let y = _mm256_fmadd_pd(
                c2,
                _mm256_broadcast_sd(&v.e3),
                _mm256_fmadd_pd(
                    c1,
                    _mm256_broadcast_sd(&v.e2),
                    _mm256_mul_pd(c0, _mm256_broadcast_sd(&v.e1)),
                ),
            );
            // SAFETY: as for f32: slot `i` starts at double `3 i`, and the fourth
            // double written is the first component of slot `i + 1 <= last`.
            unsafe { _mm256_storeu_pd(output.add(3 * i), y) };
        }
        out[last] = crate::kernels::f64::apply(&m, &x[last]);
    }
}
