//! The kinds of check run beside one another on the machine's cores, each
//! into a report of its own, merged in the kinds' order: the report is the
//! one running them in order would write, whichever finishes first.

use std::thread::{self, ScopedJoinHandle};

use super::kind::CheckKind;
use crate::context::Context;
use crate::reference::ReferenceError;
use crate::report::Report;

/// Where a run of [`run_merged`] is, for progress and for the work that
/// waits on the figures' data.
#[derive(Clone, Copy, Debug)]
pub enum Merge<'a> {
    /// Kind `index` is what the run waits for next.
    Awaiting {
        /// Which kind, from 0.
        index: usize,
        /// Its name in English and in Hungarian.
        names: [&'static str; 2],
    },
    /// Every kind that [feeds the figures](CheckKind::feeds_figures) has
    /// finished: `report` holds their [figure data](Report::figure_data),
    /// merged in the kinds' order, whatever the others are still doing.
    FigureData {
        /// The figures' data.
        report: &'a Report,
    },
}

type Part = Result<Report, ReferenceError>;

/// Runs `kinds` into `report`, merging their results in the kinds' order
/// and calling `step` with the figures' data as soon as it is whole, then
/// as each kind is awaited. Every kind starts at once on a
/// thread of its own, but one that [measures time](CheckKind::measures_time)
/// runs alone when its turn comes, after every other kind has finished.
/// The first error in the kinds' order is returned; a kind's panic is
/// resumed here.
pub fn run_merged<E: From<ReferenceError>>(
    kinds: &[Box<dyn CheckKind>],
    context: &Context,
    report: &mut Report,
    mut step: impl FnMut(Merge) -> Result<(), E>,
) -> Result<(), E> {
    let (quick, command) = (report.quick, report.command.clone());
    let run = |kind: &dyn CheckKind| -> Part {
        let mut part = Report::new(quick, &command);
        kind.run(context, &mut part).map(|()| part)
    };
    thread::scope(|scope| {
        let mut running: Vec<Option<ScopedJoinHandle<Part>>> = kinds
            .iter()
            .map(|kind| {
                let kind = kind.as_ref();
                (!kind.measures_time()).then(|| scope.spawn(move || run(kind)))
            })
            .collect();
        let mut finished: Vec<Option<Part>> = kinds.iter().map(|_| None).collect();
        // The figures wait only for the kinds that feed them (those that
        // run beside the others: one that measures time comes in its turn).
        let feeding: Vec<usize> = (0..kinds.len())
            .filter(|&i| kinds[i].feeds_figures() && running[i].is_some())
            .collect();
        let mut figures = Report::new(quick, &command);
        let mut complete = !feeding.is_empty();
        for &i in &feeding {
            let part = joined(running[i].take().expect("each kind runs once"));
            match &part {
                Ok(part) => figures.absorb(part.figure_data()),
                Err(_) => complete = false,
            }
            finished[i] = Some(part);
        }
        if complete {
            step(Merge::FigureData { report: &figures })?;
        }
        for (index, kind) in kinds.iter().enumerate() {
            step(Merge::Awaiting {
                index,
                names: [kind.name(), kind.name_hu()],
            })?;
            let part = if kind.measures_time() {
                for (later, handle) in running.iter_mut().enumerate().skip(index + 1) {
                    if let Some(handle) = handle.take() {
                        finished[later] = Some(joined(handle));
                    }
                }
                run(kind.as_ref())
            } else {
                match finished[index].take() {
                    Some(part) => part,
                    None => joined(running[index].take().expect("each kind runs once")),
                }
            };
            report.absorb(part?);
        }
        Ok(())
    })
}

/// A kind's part, or its panic resumed on this thread.
fn joined(handle: ScopedJoinHandle<Part>) -> Part {
    handle
        .join()
        .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
}
