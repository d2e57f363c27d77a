//! Cold functions that leave the caller's vector registers alone
//! ([`keeps_vector_registers!`](crate::num::cold::keeps_vector_registers)).
//!
//! A scalar kernel inlined into a caller's loop keeps its loop-invariant
//! values (the primitive's widened components, the constants of its
//! bound) in vector registers. One call out of line to a later stage,
//! even one the loop never takes, makes the compiler keep them in memory
//! instead and load them again on every iteration: the Rust calling
//! convention saves no vector register across a call. Declared with this
//! macro, the function is `extern "win64"` on x86-64, whose callee saves
//! `xmm6` to `xmm15` (their low 128 bits): the caller's values stay in
//! those registers, and the cold function saves the ones it uses, on its
//! own path. Elsewhere it keeps the Rust calling convention.
//!
//! In the kernels bench (`cargo bench --bench kernels`, 4,096 primary
//! rays, filtered runs of the reference and plain f64 alone, fastest
//! interleaved passes) the plane's scalar reference took 1.35× plain
//! f64's time with its second pass in the Rust convention, and 1.29× to
//! 1.30× with it in `win64`. Only the plane's uses it: the same for the
//! sphere's first cold stage left it at 1.12× to 1.15×, and for the
//! quadric's took it from 1.24× to between 1.39× and 1.42×.

/// `fn` items in the calling convention described in the
/// [module](self): attributes, visibility, generics and body as written.
macro_rules! keeps_vector_registers {
    ($(#[$m:meta])* $vis:vis fn $name:ident $($rest:tt)*) => {
        #[cfg(target_arch = "x86_64")]
        $(#[$m])*
        // The types cross no foreign boundary: Rust calls Rust.
        #[allow(improper_ctypes_definitions)]
        $vis extern "win64" fn $name $($rest)*

        #[cfg(not(target_arch = "x86_64"))]
        $(#[$m])*
        $vis fn $name $($rest)*
    };
}
pub(crate) use keeps_vector_registers;
