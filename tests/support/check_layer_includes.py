#!/usr/bin/python3
"""Checks that every library layer includes only the layers its CMake target links (docs/architecture.md).

    tests/support/check_layer_includes.py [ROOT]

A layer is a folder, src/<area> with include/mdr/<area>; a file of it that includes "mdr/<other>/..." (a public
header) or "<other>/..." (an internal one, from src/) depends on <other>. The rule is the libraries' link order in
CMakeLists.txt: mdr_core (the physics), then mdr_io (case and result files) and mdr_instrument (instrument files)
beside each other, mdr_fit (the identification, with Ceres) over the core only (its curves are arrays), and
mdr_fitcase (the fit case and the reading of its curves' files) over all of them. So fit cannot include io or
instrument, nor io fit: the cycle that issue 27 broke cannot come back. Prints each include that breaks the rule (file, line, layer) and exits 1; exits 0 when none does.
ROOT is the repository (default: the one this script is in)."""
import pathlib
import re
import sys

CORE = {"numerics", "rheology", "profile", "foundation", "contact", "drivers", "dem", "parallel"}
# Layer -> the layers it may include (its own included). Every layer of src/ must be listed.
ALLOWED = {
    **{layer: CORE for layer in CORE},
    "io": CORE | {"io"},
    "instrument": CORE | {"instrument"},
    "fit": CORE | {"fit"},
    "fitcase": CORE | {"io", "instrument", "fit", "fitcase"},
}
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]+"(?:mdr/)?([a-z_]+)/', re.MULTILINE)


def violations(root):
    """[(path, line, layer, included layer)] of the includes that break ALLOWED; an unlisted layer is one too."""
    found = []
    layers = sorted({path.name for base in ("src", "include/mdr") for path in (root / base).iterdir() if path.is_dir()})
    for layer in layers:
        if layer not in ALLOWED:
            found.append((root / "src" / layer, 0, layer, "(a layer not in ALLOWED)"))
            continue
        for base in ("src", "include/mdr"):
            for path in sorted((root / base / layer).rglob("*")):
                if path.suffix not in (".cpp", ".hpp", ".h"):
                    continue
                text = path.read_text(encoding="utf-8", errors="replace")
                for match in INCLUDE.finditer(text):
                    included = match.group(1)
                    if included in layers and included not in ALLOWED[layer]:
                        found.append((path.relative_to(root), text.count("\n", 0, match.start()) + 1, layer, included))
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    found = violations(root)
    for path, line, layer, included in found:
        print(f"{path}:{line}: layer {layer} includes {included}, which its library does not link")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
