//! Batches that stream (`compare --pairs`, `fit --target -`): records are pulled from their input as
//! they arrive, worked on in parallel one chunk at a time, and handed on in input order as soon as
//! their chunk is done — the first result is out before the last record is read, and memory holds
//! one chunk, however long the input.

use rayon::prelude::*;

/// The largest chunk, per thread. Chunks start at one record, so that the first result comes out
/// as soon as the first record is in (a slow producer upstream is never waited for beyond it), and
/// double after each chunk up to this, so long batches keep every thread busy between the waits at
/// chunk ends.
const LAST_CHUNK_PER_THREAD: usize = 32;

/// Runs `work` on every record of `records` (in parallel within a chunk) and passes each result to
/// `emit` in input order, a chunk at a time. Stops at the first error of `records` or of `emit`
/// (after emitting the results of the records read before it), or when `emit` returns `Ok(false)`
/// (the reader went away). The results are those of running `work` on each record in turn.
pub fn in_order<I: Send, O: Send, E>(
    mut records: impl Iterator<Item = Result<I, E>>,
    work: impl Fn(I) -> O + Sync,
    mut emit: impl FnMut(O) -> Result<bool, E>,
) -> Result<(), E> {
    let largest = LAST_CHUNK_PER_THREAD * rayon::current_num_threads().max(1);
    let mut size = 1;
    loop {
        let mut chunk = Vec::with_capacity(size);
        let mut ended = None;
        for record in records.by_ref() {
            match record {
                Ok(record) => chunk.push(record),
                Err(e) => {
                    ended = Some(e);
                    break;
                }
            }
            if chunk.len() == size {
                break;
            }
        }
        let full = chunk.len() == size;
        let results: Vec<O> = chunk.into_par_iter().map(&work).collect();
        for result in results {
            if !emit(result)? {
                return Ok(());
            }
        }
        if let Some(e) = ended {
            return Err(e);
        }
        if !full {
            return Ok(());
        }
        size = (2 * size).min(largest);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_in_input_order_and_stop_where_the_input_or_the_reader_does() {
        let squares = |n: usize| -> Vec<usize> {
            let mut out = Vec::new();
            in_order(
                (0..n).map(Ok::<_, ()>),
                |i| i * i,
                |o| {
                    out.push(o);
                    Ok(true)
                },
            )
            .unwrap();
            out
        };
        for n in [0, 1, 7, 1000] {
            assert_eq!(squares(n), (0..n).map(|i| i * i).collect::<Vec<_>>());
        }
        // An input error ends the batch after the records read before it.
        let mut out = Vec::new();
        let input = (0..10).map(|i| if i == 6 { Err("broken") } else { Ok(i) });
        let ended = in_order(
            input,
            |i| i + 1,
            |o| {
                out.push(o);
                Ok(true)
            },
        );
        assert_eq!((ended, out), (Err("broken"), vec![1, 2, 3, 4, 5, 6]));
        // A reader that goes away stops the work.
        let mut seen = 0;
        in_order(
            (0..1000).map(Ok::<_, ()>),
            |i| i,
            |_| {
                seen += 1;
                Ok(seen < 3)
            },
        )
        .unwrap();
        assert_eq!(seen, 3);
    }
}
