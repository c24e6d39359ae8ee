#!/usr/bin/env bash
# The distributed tests under AddressSanitizer and UndefinedBehaviorSanitizer, outside CI (CI's
# asan build has no MPI, to stay within its time): builds the asan preset with MPI into
# build/asan-mpi (about 15 minutes on 2 cores), then runs tests/distributed on 1 to 5 ranks.
# LeakSanitizer is off: OpenMPI keeps what MPI_Init set up until exit, in components it unloads
# before the leak check, so LSan reports those leaks with frames it cannot name (no texsplat
# frame among them, checked 2026-11-29); memory errors and undefined behaviour are still fatal.
# Usage: scripts/sanitize-distributed.sh [ranks...]   (default: 1 2 3 4 5)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build/asan-mpi"
cd "$root"
cmake --preset asan -B "$build" -DTEXSPLAT_WITH_MPI=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target texsplat_distributed_tests
ranks=("$@")
[ ${#ranks[@]} -gt 0 ] || ranks=(1 2 3 4 5)
root_flag=()
[ "$(id -u)" -ne 0 ] || root_flag=(--allow-run-as-root)
export ASAN_OPTIONS=detect_leaks=0
status=0
for n in "${ranks[@]}"; do
    log="$build/distributed-$n.log"
    if mpirun "${root_flag[@]}" --oversubscribe -np "$n" -x ASAN_OPTIONS \
        "$build/tests/distributed/texsplat_distributed_tests" >"$log" 2>&1; then
        echo "$n ranks: passed ($(grep -m1 -o '[0-9]* tests' "$log"))"
    else
        echo "$n ranks: FAILED, see $log"
        status=1
    fi
done
exit $status
