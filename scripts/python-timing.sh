#!/usr/bin/env bash
# The time from `import texsplat` to a PNG of a 256³ float32 array, against `texsplat render` of
# the same array saved as .npy (docs/results.md, "From Python"). Each is run three times in a
# fresh process; both read the array from the same .npy file and write a 512x512 PNG on the CPU
# backend.
#
# Usage: scripts/python-timing.sh PYTHON TEXSPLAT [WORK_DIR]
#   PYTHON: the venv's python with texsplat installed; TEXSPLAT: the command line.
set -euo pipefail
python=$1
texsplat=$2
work=${3:-$(mktemp -d)}
mkdir -p "$work"
cd "$work"
"$python" - <<'PY'
import numpy as np
n = 256
z, y, x = np.ogrid[-1:1:n * 1j, -1:1:n * 1j, -1:1:n * 1j]
ring = np.sqrt(x**2 + y**2) - 0.55
np.save("field.npy", (np.exp(-(ring**2 + z**2) / 0.03) * (1.2 + x)).astype(np.float32))
PY
cat > field.iv <<'IV'
#Inventor V2.1 ascii
Separator {
    VolumeData { source FILE_NPY fileName "field.npy" }
    TransferFunction { preset VIRIDIS unitDistance 0 }
    TextureSplat { }
}
IV
for run in 1 2 3; do
    "$python" -c '
import time
start = time.perf_counter()
import numpy as np
import texsplat
texsplat.render(np.load("field.npy"), size=(512, 512), backend="cpu").save("python.png")
print(f"python: import texsplat to image: {time.perf_counter() - start:.2f} s")'
    TIMEFORMAT="texsplat render: %R s"
    time "$texsplat" render field.iv -o cli.png --size 512x512 --backend cpu
done
# The same array, transfer function and camera: the same picture.
cmp python.png cli.png && echo "python.png and cli.png are identical"
