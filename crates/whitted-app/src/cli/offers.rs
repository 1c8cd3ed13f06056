//! Which chapter first offers each group of arguments: the first chapter that needs it. The
//! command line reads them to build a chapter's arguments, and the window's keys read them too
//! (views from [`OBJECTS_FROM`], depth and supersampling from [`TRACING_FROM`]).
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use whitted::render::Chapter;

/// The chapter from which the binaries offer [`Objects`](super::args::Objects): the first
/// that traces objects.
pub const OBJECTS_FROM: Chapter = Chapter::GenericObjects;
/// The chapter from which the binaries offer [`Accuracy`](super::args::Accuracy): the first
/// with secondary rays.
pub const ACCURACY_FROM: Chapter = Chapter::Shadows;
/// The chapter from which the binaries offer [`Tracing`](super::args::Tracing): the first
/// with recursion.
pub const TRACING_FROM: Chapter = Chapter::ReflectionRefraction;
