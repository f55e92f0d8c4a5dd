"""ParaView collections (.pvd): the one module that writes and reads them.

read_collection(path) reads a .pvd (fix membrane2d's and fix membrane3d's FILE.pvd,
run.pvd) with an XML parser: [DataSet(timestep, part, name, path)].

Collect the ParaView files of one biaxial shear into FOLDER/run.pvd: a time series
whose every step holds the particles, the contacts, the walls and (membrane case) the
membrane of that step, so that ParaView opens the whole run in one click.

    paraview_collection.py FOLDER      (the folder of -var vtkdir, examples/biaxial)

The steps are those of the particle files (particles_<step>.vtp); a kind whose file of
that step is missing (the membrane before shear, a rigid-wall run) is left out of that
step. doc/paraview.md describes the files."""
import collections
import os
import re
import sys
import xml.etree.ElementTree as ET

DataSet = collections.namedtuple("DataSet", "timestep part name path")


def read_collection(path):
    """The data sets of a .pvd file, in its order: DataSet(timestep (float), part (int),
    name (str, '' without one), path (the file, relative to the .pvd's folder)).
    OSError: no such file; ValueError: not a VTK collection."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise ValueError(f"{path}: not an XML file ({e})") from None
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise ValueError(f"{path}: not a VTK collection (VTKFile type=\"Collection\")")
    folder = os.path.dirname(path)
    return [DataSet(float(d.get("timestep", "0")), int(d.get("part", "0")), d.get("name", ""),
                    os.path.join(folder, d.get("file")))
            for d in root.iter("DataSet") if d.get("file")]


def collection_frames(path, part=0):
    """[(step, path)] of the data sets of one part of a .pvd ([] without the file)."""
    if not os.path.exists(path):
        return []
    return [(int(round(d.timestep)), d.path) for d in read_collection(path) if d.part == part]

# the kinds of file in the folder, in the order of their parts in run.pvd
KINDS = ("particles", "contacts", "walls", "membrane")


def frames(names):
    """{kind: {step: file name}} of the .vtp files among `names`."""
    found = {k: {} for k in KINDS}
    for n in names:
        m = re.fullmatch(r"(%s)_(\d+)\.vtp" % "|".join(KINDS), n)
        if m:
            found[m.group(1)][int(m.group(2))] = n
    return found


def collection(names):
    """The text of run.pvd for a folder holding the files `names`."""
    found = frames(names)
    rows = []
    for step in sorted(found["particles"]):
        for part, kind in enumerate(KINDS):
            if step in found[kind]:
                rows.append('    <DataSet timestep="%d" part="%d" name="%s" file="%s"/>'
                            % (step, part, kind, found[kind][step]))
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
            + "".join(r + "\n" for r in rows) + "  </Collection>\n</VTKFile>\n")


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) == 2 else 2
    folder = argv[1]
    if not os.path.isdir(folder):
        print("paraview_collection.py: no folder %s (the -var vtkdir of the shear)" % folder,
              file=sys.stderr)
        return 1
    names = os.listdir(folder)
    if not frames(names)["particles"]:
        # not an error: a shear shorter than -var vtkstrain ends before its first frame
        print("paraview_collection.py: note: no particles_<step>.vtp in %s, no run.pvd written "
              "(the shear ended before its first ParaView frame, or ran with -var vtkstrain 0)"
              % folder, file=sys.stderr)
        return 0
    with open(os.path.join(folder, "run.pvd"), "w") as f:
        f.write(collection(names))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
