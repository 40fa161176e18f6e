"""Zip the Blender add-on: ``python blender/make_zip.py OUT_FOLDER`` writes
OUT_FOLDER/facesynth_blender.zip, which Blender installs (Edit > Preferences > Add-ons >
Install...). ``make blender-addon`` runs it; the headless Blender test builds its zip with
:func:`build` too."""

from __future__ import annotations

import sys
import zipfile
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent / "facesynth_blender"
NAME = "facesynth_blender.zip"


def build(folder: Path) -> Path:
    """Write ``folder/facesynth_blender.zip``: the package's ``.py`` files under
    ``facesynth_blender/``, in a fixed order and with fixed times, so the same sources give the
    same bytes. Returns its path."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = folder / NAME
    tmp = out.with_name(out.name + ".tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(PACKAGE.glob("*.py")):
            info = zipfile.ZipInfo(f"{PACKAGE.name}/{path.name}", date_time=(2024, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            zf.writestr(info, path.read_bytes())
    tmp.replace(out)
    return out


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: python blender/make_zip.py OUT_FOLDER")
    print(f"wrote {build(Path(sys.argv[1]))}")
