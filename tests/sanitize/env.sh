# The sanitizer stage's run-time options, in one place. Sourced by ./dev test --sanitize; by
# hand: `source tests/sanitize/env.sh build-sanitize` before running a sanitized binary.
# Every report ends the process with exit code 86 (kept apart from depthscope's 1, 2 and 3,
# timeout's 124 and signals' 128+N); tests/support/run_process.cpp also fails a test whose
# depthscope child printed a report, whatever its exit code.
_ds_san_build="$(cd "${1:?usage: source tests/sanitize/env.sh BUILD_DIR}" && pwd)"
_ds_san_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

# fast_unwind_on_malloc=1 (the default, pinned here): never the slow unwinder on allocation.
# With it, `capture --scene atrium` hangs for good: lavapipe's LLVM JIT registers its code's
# unwind tables (__register_frame), after which libgcc's _Unwind_Find_FDE calls malloc while
# holding its object_mutex; ASan's malloc then unwinds slowly, re-enters _Unwind_Find_FDE and
# waits on the mutex its own thread holds (gdb: lavapipe's queue thread, MCJIT::finalizeObject >
# registerEHFrames > operator new > UnwindSlow > _Unwind_Find_FDE > malloc > UnwindSlow >
# _Unwind_Find_FDE > pthread_mutex_lock; the main thread waits in submit_once). The price:
# allocation stacks stop at the first library built without frame pointers (lavapipe, LLVM,
# the validation layer), so suppressions match libraries, not functions.
export ASAN_OPTIONS="halt_on_error=1:exitcode=86:detect_leaks=1:fast_unwind_on_malloc=1"
export UBSAN_OPTIONS="halt_on_error=1:exitcode=86:print_stacktrace=1"
# print_suppressions=0: a suppressed leak must not add lines to stderr (the CLI tests count them).
export LSAN_OPTIONS="exitcode=86:suppressions=$_ds_san_dir/lsan.supp:print_suppressions=0"
# See keep_loaded.c: libraries stay mapped until LeakSanitizer's check at exit.
export LD_PRELOAD="$_ds_san_build/libds_keep_loaded.so${LD_PRELOAD:+:$LD_PRELOAD}"
unset _ds_san_build _ds_san_dir
