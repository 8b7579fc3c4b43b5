//! The ordered parallel driver of a batch: workers take blocks of input in turn and render
//! them; this thread writes the rendered blocks in input order as they are ready, with a bounded
//! number in flight.

use crate::input::{Block, Blocks};
use crate::render::Rendered;
use std::sync::{Condvar, Mutex};

/// Renders `blocks` on `threads` workers and writes them in input order as they are ready: each
/// worker takes the next block from the reader (under a lock), renders it and sends it to this
/// thread, which writes the blocks in order. At most `4 × threads` blocks are taken and not yet
/// written, so memory stays bounded however far one slow block holds the order back. Returns
/// false when `write` reports stdout closed (the workers then stop).
pub(crate) fn ordered_parallel(
    threads: usize,
    blocks: &mut Blocks,
    render: &(dyn Fn(&Block) -> Rendered + Sync),
    write: &mut dyn FnMut(Rendered) -> bool,
) -> bool {
    let limit = 4 * threads;
    // (reader, next sequence number, blocks in flight, stop)
    let state = Mutex::new((blocks, 0usize, 0usize, false));
    let room = Condvar::new();
    let (tx, rx) = std::sync::mpsc::channel::<(usize, Rendered)>();
    std::thread::scope(|scope| {
        for _ in 0..threads {
            let tx = tx.clone();
            let (state, room) = (&state, &room);
            scope.spawn(move || {
                loop {
                    let (seq, block) = {
                        let mut s = state.lock().unwrap_or_else(|p| p.into_inner());
                        while s.2 >= limit && !s.3 {
                            s = room.wait(s).unwrap_or_else(|p| p.into_inner());
                        }
                        if s.3 {
                            return;
                        }
                        let Some(block) = s.0.next() else { return };
                        s.1 += 1;
                        s.2 += 1;
                        (s.1 - 1, block)
                    };
                    if tx.send((seq, render(&block))).is_err() {
                        return;
                    }
                }
            });
        }
        drop(tx);
        let mut waiting: std::collections::BTreeMap<usize, Rendered> = std::collections::BTreeMap::new();
        let mut next = 0;
        let mut open = true;
        for (seq, r) in rx {
            waiting.insert(seq, r);
            while let Some(r) = waiting.remove(&next) {
                next += 1;
                open = open && write(r);
                let mut s = state.lock().unwrap_or_else(|p| p.into_inner());
                s.2 -= 1;
                s.3 |= !open;
                room.notify_all();
            }
            if !open {
                break;
            }
        }
        open
    })
}

/// The workers of `--threads N`: `N` (0: every core), but never more than the machine's cores
/// nor more than `items`, the pieces of work there are when they are known (one curve, one
/// path): more threads would only be started to wait.
pub fn worker_count(requested: usize, items: Option<usize>) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
    let wanted = if requested == 0 { cores } else { requested.min(cores) };
    items.map_or(wanted, |n| wanted.min(n.max(1)))
}

/// The worker pool of `--threads N` ([`worker_count`] threads for `items` pieces of work, when
/// known); `None` after saying why on stderr.
pub fn thread_pool(threads: usize, items: Option<usize>) -> Option<rayon::ThreadPool> {
    let n = worker_count(threads, items);
    match rayon::ThreadPoolBuilder::new().num_threads(n).build() {
        Ok(p) => Some(p),
        Err(e) => {
            eprintln!("casteljau: cannot start {n} threads: {e}");
            None
        }
    }
}
