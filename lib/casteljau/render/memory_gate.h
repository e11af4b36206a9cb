// One thread at a time past a few megabytes of stroke working memory.
//
// Why: hostile input can make a stroke's outline amplify a small file into
// gigabytes (round joins on a stroke 1e6 px wide, a circle 1e61 px tall,
// a million dashes); the stroker's point limit (stroker.h) bounds one call,
// about 600 MB at worst, but every thread of a frame, and every file of a
// batch, makes its own calls at once: eight threads took 1.5 GB on such a
// file, and the CLI's default is one thread per core. So a renderer's
// stroker passes this gate once its working buffers grow past kUngated
// elements (stroker.cpp: a few megabytes), and the renderer, once the
// stroke is painted, frees those buffers and leaves (Renderer::draw_stroke).
// The memory of all threads together is then at most one full call plus the
// others' few megabytes, whatever the number of threads; the picture does
// not change, only the order in which such strokes are drawn.
//
// Invariants. The gate is one process-wide mutex with a per-thread depth, so
// a thread already through it passes again without waiting (a pattern
// tile's stroke drawn while the stroke it paints holds it). No thread waits
// on another while through it: it is left before a renderer returns from
// the stroke, so neither a band's pool nor a batch's workers can deadlock
// on it.
#pragma once

namespace casteljau::memory_gate {

/// Waits until no other thread is through the gate, then passes it (again,
/// one level deeper, when this thread already is).
void enter();

/// Leaves one level; the last one lets the next thread through.
void leave();

/// How many times this thread is through the gate (0: it is not).
int depth();

} // namespace casteljau::memory_gate
