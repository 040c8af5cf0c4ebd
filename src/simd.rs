//! Run-time dispatch of the bulk loops to wider vector code (feature `simd-dispatch`).
//!
//! The bank scans, the array forms (`ton_array`, `call_array`) and the timer area's tick are
//! straight-line loops that LLVM vectorizes for whatever the build targets. The default x86-64 target has SSE2 only: 16 bytes per
//! instruction, two-operand forms (a value still needed costs a register copy), no byte or
//! word select. A library cannot choose its users' `-C target-cpu`, but with `std` it can ask
//! the CPU what it has (`is_x86_feature_detected!`) and run the same loop compiled for AVX2
//! (32 bytes per instruction, three-operand forms) or AVX-512BW (64 bytes, mask registers).
//! The loop is one function, [`Kernel::run`], inlined into one wrapper per extension: no
//! second copy of any logic, and the proofs that run with the feature on exercise the wrapper
//! this CPU takes.
//!
//! Without the feature (or on another architecture) [`run`] calls the kernel directly, and the
//! crate keeps `#![forbid(unsafe_code)]`.

/// A loop over many instances, to be compiled once per vector extension: `run` must be
/// `#[inline(always)]`, so that its body (and every function it inlines) is compiled inside
/// each wrapper with the wrapper's extension enabled.
pub(crate) trait Kernel {
    /// The loop.
    fn run(self);

    /// The loop as compiled for AVX2 and AVX-512: [`run`](Self::run) unless the loop's
    /// shape depends on the vector width (groups sized for SSE2's 16 registers of 16 bytes
    /// hold back a loop that could fill 64-byte registers).
    #[cfg_attr(
        not(all(feature = "simd-dispatch", target_arch = "x86_64")),
        allow(dead_code)
    )]
    #[inline(always)]
    fn run_wide(self)
    where
        Self: Sized,
    {
        self.run();
    }
}

/// Runs `kernel` compiled for the widest vector extension this CPU has (with the feature
/// `simd-dispatch` on x86-64), else as the build targets.
#[inline(always)]
pub(crate) fn run<K: Kernel>(kernel: K) {
    #[cfg(all(feature = "simd-dispatch", target_arch = "x86_64"))]
    {
        if std::is_x86_feature_detected!("avx512bw") {
            // SAFETY: a function with `#[target_feature]` may use the instructions of those
            // features, and calling it on a CPU without them is undefined behaviour (an
            // illegal instruction at best); that is the only obligation the call has. The
            // features it enables, `avx512f` and `avx512bw`, were detected at run time on
            // this CPU just above (`is_x86_feature_detected!` asks CPUID, and the operating
            // system's XCR0 for the register state, and caches the answer). The kernel
            // itself is safe code.
            #[allow(unsafe_code)]
            unsafe {
                x86::avx512(kernel)
            };
            return;
        }
        if std::is_x86_feature_detected!("avx2") {
            // SAFETY: as above: `avx2` was detected on this CPU just above.
            #[allow(unsafe_code)]
            unsafe {
                x86::avx2(kernel)
            };
            return;
        }
    }
    kernel.run();
}

#[cfg(all(feature = "simd-dispatch", target_arch = "x86_64"))]
mod x86 {
    use super::Kernel;

    /// `kernel` compiled with AVX2.
    #[target_feature(enable = "avx2")]
    pub(super) fn avx2<K: Kernel>(kernel: K) {
        kernel.run_wide();
    }

    /// `kernel` compiled with AVX-512 (foundation and byte/word instructions).
    #[target_feature(enable = "avx512f,avx512bw")]
    pub(super) fn avx512<K: Kernel>(kernel: K) {
        kernel.run_wide();
    }
}
