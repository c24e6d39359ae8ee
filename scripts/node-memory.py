#!/usr/bin/python3
"""What a scene node costs in memory: peak resident size of `texsplat info` on a scene of COUNT
nodes of one type, less that of a scene of one, per node (issue 14).

    scripts/node-memory.py build/ci/apps/texsplat [COUNT] [TYPE ...]

writes `<TYPE>-<COUNT>.iv` (a Separator holding COUNT `TYPE {}`) and `<TYPE>-1.iv` in a temporary
folder, runs `/usr/bin/time -f %M texsplat info FILE > /dev/null` on each and prints a table.
COUNT is 1000000 by default, the types Group, Separator and Transform.
"""

import os
import subprocess
import sys
import tempfile


def write_scene(path, node_type, count):
    with open(path, "w") as scene:
        scene.write("#Inventor V2.1 ascii\nSeparator {\n")
        scene.write(("  %s {}\n" % node_type) * count)
        scene.write("}\n")


def peak_kib(texsplat, path):
    """Peak resident size, KiB, as GNU time's %M reports it."""
    result = subprocess.run(["/usr/bin/time", "-f", "%M", texsplat, "info", path],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            check=True)
    return int(result.stderr.strip().splitlines()[-1])


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    texsplat = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 1000000
    types = sys.argv[3:] or ["Group", "Separator", "Transform"]
    print("| scene of %d | file | peak resident less a one-node scene | per node |" % count)
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as folder:
        for node_type in types:
            many = os.path.join(folder, "%s-%d.iv" % (node_type, count))
            one = os.path.join(folder, "%s-1.iv" % node_type)
            write_scene(many, node_type, count)
            write_scene(one, node_type, 1)
            grown = (peak_kib(texsplat, many) - peak_kib(texsplat, one)) * 1024
            print("| `%s {}` | %.0f MB | %.0f MiB | %.0f B |" % (
                node_type, os.path.getsize(many) / 1e6, grown / 2**20, grown / count))
            os.remove(many)


if __name__ == "__main__":
    main()
