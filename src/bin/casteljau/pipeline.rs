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

/// The worker pool of `--threads N` (0: all cores); `None` after saying why on stderr.
pub fn thread_pool(threads: usize) -> Option<rayon::ThreadPool> {
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(p) => Some(p),
        Err(e) => {
            eprintln!("casteljau: cannot start {threads} threads: {e}");
            None
        }
    }
}
