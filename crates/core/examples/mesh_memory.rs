//! Peak memory of one build, counted by a wrapping global allocator.
//!
//! `cargo run --release -p edgewise-core --example mesh_memory -- [nu nv]`
//!
//! For each structure it generates the torus, then counts every byte the build
//! allocates: the peak held at once during the build, against what the
//! finished structure holds. The input polygon list is not counted (it exists
//! before and after). The half-edge build is the first in the process, so its
//! time includes every page fault of fresh memory.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use edgewise_core::mesh::{HalfEdgeId, HalfEdgeMesh, WingedEdgeMesh, generate};

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

fn grew(bytes: usize) {
    let now = CURRENT.fetch_add(bytes, Ordering::Relaxed) + bytes;
    PEAK.fetch_max(now, Ordering::Relaxed);
}

fn shrank(bytes: usize) {
    CURRENT.fetch_sub(bytes, Ordering::Relaxed);
}

/// The system allocator, counting live bytes and their peak.
struct Counting;

// Measuring allocations needs a global allocator, which is an unsafe trait;
// this one only forwards to the system allocator.
#[allow(unsafe_code)]
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged; the caller upholds `alloc`'s contract.
        let pointer = unsafe { System.alloc(layout) };
        if !pointer.is_null() {
            grew(layout.size());
        }
        pointer
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as for `alloc`.
        let pointer = unsafe { System.alloc_zeroed(layout) };
        if !pointer.is_null() {
            grew(layout.size());
        }
        pointer
    }

    unsafe fn dealloc(&self, pointer: *mut u8, layout: Layout) {
        // SAFETY: as for `alloc`.
        unsafe { System.dealloc(pointer, layout) };
        shrank(layout.size());
    }

    unsafe fn realloc(&self, pointer: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: as for `alloc`.
        let moved = unsafe { System.realloc(pointer, layout, new_size) };
        if !moved.is_null() {
            // Count the new block before releasing the old one: a moving
            // reallocation holds both for a moment.
            grew(new_size);
            shrank(layout.size());
        }
        moved
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn mib(bytes: usize) -> f64 {
    bytes as f64 / 1_048_576.0
}

/// Runs `build` with the peak reset; reports its peak, the size of what it
/// returned, and its time.
fn measure<T>(name: &str, build: impl FnOnce() -> T) -> T {
    let before = CURRENT.load(Ordering::Relaxed);
    PEAK.store(before, Ordering::Relaxed);
    let start = Instant::now();
    let result = build();
    let elapsed = start.elapsed();
    let (peak, kept) = (
        PEAK.load(Ordering::Relaxed) - before,
        CURRENT.load(Ordering::Relaxed) - before,
    );
    println!(
        "{name}: build {:.1} ms; holds {:.1} MiB; peak during the build {:.1} MiB = {:.2} x",
        elapsed.as_secs_f64() * 1e3,
        mib(kept),
        mib(peak),
        peak as f64 / kept.max(1) as f64
    );
    result
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let number =
        |i: usize, default: u32| args.get(i).and_then(|a| a.parse().ok()).unwrap_or(default);
    let (nu, nv) = (number(0, 1000), number(1, 500));
    let polygons = generate::torus(nu, nv);
    println!("torus {nu}x{nv}: {} triangles", polygons.face_count());
    let half = measure("half-edge  ", || HalfEdgeMesh::build(&polygons));
    let before = CURRENT.load(Ordering::Relaxed);
    if let Ok((mesh, _)) = &half {
        let _ = mesh.predecessor_edge(HalfEdgeId::new(0));
        println!(
            "  (the predecessor table, built on the first predecessor_edge call, adds {:.1} MiB)",
            mib(CURRENT.load(Ordering::Relaxed) - before)
        );
    }
    drop(half);
    let winged = measure("winged-edge", || WingedEdgeMesh::build(&polygons));
    drop(winged);
}
