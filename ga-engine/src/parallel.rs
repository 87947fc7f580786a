//! The slice steps on rayon's pool.
//!
//! The slice is cut into chunks of a fixed length, whatever the number of threads, and
//! each body's result depends only on that body (see `slice.rs`), so one thread and
//! sixty-four give the same bits.

use rayon::prelude::*;

/// Bodies per task: enough to amortise a task (a few microseconds of work), a multiple
/// of every group width.
const CHUNK: usize = 512;

/// `f` on each fixed chunk of `states`, in parallel.
pub(crate) fn for_chunks<S: Send>(states: &mut [S], f: impl Fn(&mut [S]) + Sync + Send) {
    states.par_chunks_mut(CHUNK).for_each(f);
}
