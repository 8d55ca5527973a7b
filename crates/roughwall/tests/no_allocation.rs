//! A call per wall hit allocates nothing (issue 9): this test binary counts every heap
//! allocation and calls `rw_rebound` (and the Rust `WallModel::rebound` behind it) on good and
//! bad hits, elastic and Sommerfeld–Huber.

use roughwall::ffi::{
    rw_hit, rw_rebound, rw_result, rw_wall_free, rw_wall_new, rw_wall_params,
    rw_wall_params_default, RW_LAW_SOMMERFELD_HUBER, RW_OK, RW_PRESET_GLASS_STEEL,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    /// Allocations made by this thread (the test harness's own threads allocate too).
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn rw_rebound_allocates_nothing() {
    for law in [0, RW_LAW_SOMMERFELD_HUBER] {
        let mut p = std::mem::MaybeUninit::<rw_wall_params>::uninit();
        let mut p = unsafe {
            rw_wall_params_default(p.as_mut_ptr());
            p.assume_init()
        };
        p.delta_xi_deg = 3.8;
        p.delta_zeta_deg = 7.5;
        p.law = law;
        if law == RW_LAW_SOMMERFELD_HUBER {
            p.preset = RW_PRESET_GLASS_STEEL;
        }
        let mut w = std::ptr::null_mut();
        assert_eq!(
            unsafe { rw_wall_new(&p, &mut w, std::ptr::null_mut(), 0) },
            RW_OK
        );
        let mut r = std::mem::MaybeUninit::<rw_result>::uninit();
        let before = allocations();
        for i in 0..10_000u64 {
            let grazing = i % 7 == 0;
            let h = rw_hit {
                velocity: [
                    5.0,
                    if grazing { -0.001 } else { -1.5 },
                    -2.0 + 1e-4 * i as f64,
                ],
                spin: [10.0, 0.0, -30.0],
                normal: [0.0, -2.0, 0.0],
                lay: [1.0, 0.2, 0.3],
                wall_velocity: [0.1, 0.0, 0.0],
                diameter: if i % 11 == 0 { -1.0 } else { 500e-6 },
                particle_id: i,
                collision_index: i % 5,
            };
            unsafe { rw_rebound(w, &h, r.as_mut_ptr()) };
        }
        assert_eq!(allocations(), before, "law {law}");
        unsafe { rw_wall_free(w) };
    }
}
