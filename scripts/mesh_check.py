#!/usr/bin/env python3
"""Check rcagd's triangle meshes with trimesh (an independent reader and mesh library).

    mesh_check.py DIR [--closed NAME ...]

For every ``*.stl``, ``*.obj``, ``*.ply`` and ``*.glb`` file of DIR: load it with
trimesh (vertices merged by position, as trimesh does by default), and report the
vertex and face counts, whether the mesh is watertight (every edge in exactly two
faces), consistently wound, and its volume. A file whose stem is named with
``--closed`` (or every file with ``--all-closed``) must be watertight, consistently
wound and have a positive volume (outward winding); its Euler characteristic is
printed too (2 for a sphere, 0 for a torus).

Exit status 0 if every checked file passes, 1 otherwise, 3 if trimesh is unavailable.
Run it through ``mesh_check.sh``, which installs trimesh into the OpenCascade venv.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

try:
    import trimesh
except ImportError:  # pragma: no cover
    print("mesh_check: trimesh is not installed", file=sys.stderr)
    sys.exit(3)


def load(path: Path):
    m = trimesh.load(str(path), force="mesh", process=True)
    return m


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("dir", type=Path)
    ap.add_argument("--closed", nargs="*", default=[], help="stems that must be closed")
    ap.add_argument("--all-closed", action="store_true", help="every mesh must be closed")
    args = ap.parse_args()
    files = sorted(
        p for p in args.dir.iterdir() if p.suffix.lower() in (".stl", ".obj", ".ply", ".glb")
    )
    if not files:
        print(f"no meshes in {args.dir}")
        return 1
    failed = 0
    for p in files:
        try:
            m = load(p)
        except Exception as e:  # noqa: BLE001 - report any reader failure
            print(f"{p.name}: cannot load: {type(e).__name__}: {e}")
            failed += 1
            continue
        must = args.all_closed or p.stem in args.closed
        line = (
            f"{p.name}: {len(m.vertices)} vertices, {len(m.faces)} faces, "
            f"watertight {m.is_watertight}, winding consistent {m.is_winding_consistent}"
        )
        if m.is_watertight:
            line += f", volume {m.volume:.9g}, Euler {m.euler_number}"
        ok = True
        if must:
            ok = m.is_watertight and m.is_winding_consistent and m.volume > 0
        print(line + ("" if not must else ("  PASS" if ok else "  FAIL (must be closed)")))
        failed += not ok
    print(f"{len(files) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
