"""The ParaView frames of a short draw-bend run, read with VTK's XML readers.

Run: tests/user/decks/vtk_drawbend.toml (wrapped strip on the 12.7 mm pin,
t = 1.04 mm over 4 layers, 25 x 2 x 4 = 200 elements and 26 x 3 x 5 = 390
nodes; Coulomb mu = 0.1 on the pin; split-form combined hardening; a flat
"floor" annulus r_max = 10 mm about (20, 0, -30) that the strip never
touches; 3 frames per step over 2 steps).  Expected answers, each with why:

 - fields.pvd lists 1 + 2 x 3 = 7 times, increasing, each with the parts
   sheet (0), pin (1) and floor (2); every file it names exists;
 - every fields_<k>.vtm reads (vtkXMLMultiBlockDataReader) as 3 blocks:
   the sheet (390 points, 200 hexahedra) and the two tools (quads);
 - the sheet carries the point fields displacement_mm, velocity_mm_s,
   contact_pressure_MPa, friction_traction_MPa, slip_rate_mm_s, slip_mm,
   contact_status, local_mu, sheet_thickness_mm and the cell fields
   stress_MPa, von_mises_MPa, plastic_strain, log_strain,
   sheet_thickness_mm, sheet_thickness_ratio, back_stress_MPa, with 1, 3 or
   6 components as named in data/cases/README.md;
 - sheet thickness: 1.04 mm to 1e-9 mm in frame 0 (the mesh is built with
   t = 1.04 and the measure, volume over mean end-face area, is exact for
   the wrapped columns' trapezoidal prisms); later in [0.90, 1.04 x 1.005]:
   bending under a back tension below yield thins the strip by a few
   percent, a 10 % loss would be a wrong measure (one layer reads 0.26 mm),
   and nothing thickens it beyond the elastic response of 40 MPa of contact
   pressure (0.06 %);
 - tools where the deck puts them: the pin's box is x, z in [-6.35, 6.35]
   (its radius about the y axis; 64 facets, vertices on the circle) to
   1e-9 mm and covers the strip's width y in [0, 12.7]; the floor's box is
   x in [10, 30], y in [-10, 10], z = -30 to 1e-9 mm;
 - accumulated slip >= 0, non-decreasing in time at every node, positive
   somewhere in the last frame, and no more than 1.05 x the largest
   displacement (a node sliding on the fixed pin moves along its surface:
   3 mm of arc on a 6.35 mm radius is 1.009 x its chord);
 - stick/slip status in {0, 1, 2}, non-zero exactly where the contact
   pressure is (both come from the same contact node); the local mu is at
   most 0.1 (1e-9) everywhere and 0.1 (1e-6) at the slipping nodes (the
   Coulomb return puts their force on the cone); |friction traction| =
   mu x pressure (1e-9 relative: both from the same force and area);
 - back stress: zero where there is no plastic strain, trace below 1e-9 of
   its largest component (it grows along the deviatoric plastic flow);
 - log strain: zero in frame 0 (1e-12);
 - the ASCII frames (vtk_format = "ascii") read back the same arrays as
   the binary ones, value for value.
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk

binary_dir, ascii_dir = sys.argv[1], sys.argv[2]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
    return ok


POINT = {"displacement_mm": 3, "velocity_mm_s": 3, "contact_pressure_MPa": 1, "friction_traction_MPa": 3,
         "slip_rate_mm_s": 1, "slip_mm": 1, "contact_status": 1, "local_mu": 1, "sheet_thickness_mm": 1}
CELL = {"stress_MPa": 6, "von_mises_MPa": 1, "plastic_strain": 1, "log_strain": 6, "sheet_thickness_mm": 1,
        "sheet_thickness_ratio": 1, "back_stress_MPa": 6}

pvd = ET.parse(os.path.join(binary_dir, "fields.pvd")).getroot()
rows = [(float(d.get("timestep")), int(d.get("part")), d.get("name"), d.get("file")) for d in pvd.iter("DataSet")]
times = sorted(set(r[0] for r in rows))
check(len(times) == 7, f"fields.pvd: {len(times)} times, expected 7")
for t in times:
    parts = sorted((r[1], r[2]) for r in rows if r[0] == t)
    check(parts == [(0, "sheet"), (1, "pin"), (2, "floor")], f"fields.pvd at t = {t}: parts {parts}")
for r in rows:
    check(os.path.exists(os.path.join(binary_dir, r[3])), f"fields.pvd names {r[3]}, which is missing")


def tuples(a):
    """A VTK data array as a list of tuples (no numpy needed)."""
    return [a.GetTuple(i) for i in range(a.GetNumberOfTuples())]


def arrays(data):
    out = {}
    for kind, d in (("point", data.GetPointData()), ("cell", data.GetCellData())):
        for i in range(d.GetNumberOfArrays()):
            out[(kind, d.GetArray(i).GetName())] = tuples(d.GetArray(i))
    out[("point", "Points")] = tuples(data.GetPoints().GetData())
    return out


def col(rows, c=0):
    return [r[c] for r in rows]


def read_frame(folder, k):
    r = vtk.vtkXMLMultiBlockDataReader()
    r.SetFileName(os.path.join(folder, f"fields_{k}.vtm"))
    r.Update()
    return r.GetOutput()


prev_slip = None
for k in range(len(times)):
    mb = read_frame(binary_dir, k)
    if not check(mb.GetNumberOfBlocks() == 3, f"frame {k}: {mb.GetNumberOfBlocks()} blocks, expected 3"):
        continue
    sheet, pin, floor = (mb.GetBlock(b) for b in range(3))
    check(sheet.GetNumberOfPoints() == 390 and sheet.GetNumberOfCells() == 200,
          f"frame {k}: sheet {sheet.GetNumberOfPoints()} points, {sheet.GetNumberOfCells()} cells")
    a = arrays(sheet)
    for kind, names in (("point", POINT), ("cell", CELL)):
        for name, comps in names.items():
            if check((kind, name) in a, f"frame {k}: no {kind} array {name}"):
                check(len(a[(kind, name)][0]) == comps, f"frame {k}: {name} has {len(a[(kind, name)][0])} components")
    if failures:
        break
    h = col(a[("point", "sheet_thickness_mm")])
    hc = col(a[("cell", "sheet_thickness_mm")])
    hmin, hmax = min(h + hc), max(h + hc)
    if k == 0:
        check(max(abs(v - 1.04) for v in h + hc) < 1e-9, f"frame 0: sheet thickness {hmin}..{hmax} mm, expected 1.04")
        check(max(abs(v) for r in a[("cell", "log_strain")] for v in r) < 1e-12, "frame 0: log strain not zero")
    else:
        check(hmin >= 0.90 and hmax <= 1.04 * 1.005,
              f"frame {k}: sheet thickness {hmin}..{hmax} mm, expected in [0.90, 1.0452]")
    pb, fb = pin.GetBounds(), floor.GetBounds()
    check(max(abs(pb[0] + 6.35), abs(pb[1] - 6.35), abs(pb[4] + 6.35), abs(pb[5] - 6.35)) < 1e-9 and pb[2] <= 0 and pb[3] >= 12.7,
          f"frame {k}: pin bounds {pb}")
    check(max(abs(fb[0] - 10), abs(fb[1] - 30), abs(fb[2] + 10), abs(fb[3] - 10), abs(fb[4] + 30), abs(fb[5] + 30)) < 1e-9,
          f"frame {k}: floor bounds {fb}")
    check(pin.GetNumberOfCells() > 0 and floor.GetNumberOfCells() > 0, f"frame {k}: a tool without facets")
    slip = col(a[("point", "slip_mm")])
    check(min(slip) >= 0, f"frame {k}: negative slip {min(slip)}")
    if prev_slip is not None:
        down = sum(1 for s1, s0 in zip(slip, prev_slip) if s1 < s0)
        check(down == 0, f"frame {k}: slip decreased at {down} nodes")
    prev_slip = slip
    status = col(a[("point", "contact_status")])
    p = col(a[("point", "contact_pressure_MPa")])
    mu = col(a[("point", "local_mu")])
    check(set(status) <= {0.0, 1.0, 2.0}, f"frame {k}: status values {set(status)}")
    check(all((st > 0) == (pi > 0) for st, pi in zip(status, p)), f"frame {k}: status and pressure disagree")
    check(max(mu) <= 0.1 + 1e-9, f"frame {k}: local mu {max(mu)} above 0.1")
    slipping = [m for m, st in zip(mu, status) if st == 2]
    if slipping:
        check(max(abs(m - 0.1) for m in slipping) < 1e-6, f"frame {k}: slipping nodes off the cone, mu {min(slipping)}")
    tmag = [math.sqrt(sum(c * c for c in r)) for r in a[("point", "friction_traction_MPa")]]
    mup = [m * pi for m, pi in zip(mu, p)]
    check(max(abs(t - q) for t, q in zip(tmag, mup)) <= 1e-9 * max(1.0, max(mup)), f"frame {k}: |traction| != mu p")
    back = a[("cell", "back_stress_MPa")]
    ep = col(a[("cell", "plastic_strain")])
    check(all(max(abs(c) for c in b) == 0 for b, e in zip(back, ep) if e == 0), f"frame {k}: back stress without plastic strain")
    big = max(abs(c) for b in back for c in b)
    check(max(abs(b[0] + b[1] + b[2]) for b in back) <= 1e-9 * max(big, 1e-300), f"frame {k}: back stress not deviatoric")
    if k == len(times) - 1:
        dmax = max(math.sqrt(sum(c * c for c in r)) for r in a[("point", "displacement_mm")])
        check(0 < max(slip) <= 1.05 * dmax, f"last frame: slip {max(slip)} mm against displacement {dmax} mm")
        check(big > 0 and max(ep) > 0, "last frame: no plastic strain or back stress")
        print(f"last frame (t = {times[-1]:.4g} s): sheet thickness {hmin:.4f}..{hmax:.4f} mm, "
              f"slip up to {max(slip):.4f} mm (largest displacement {dmax:.4f} mm), "
              f"{status.count(1.0)} sticking and {status.count(2.0)} slipping nodes, "
              f"pressure up to {max(p):.2f} MPa, plastic strain up to {max(ep):.4f}, back stress up to {big:.2f} MPa")
    # ASCII frames: the same arrays, value for value.
    asc = arrays(read_frame(ascii_dir, k).GetBlock(0))
    for key, v in a.items():
        if check(key in asc, f"frame {k}: ascii frame has no {key}"):
            check(asc[key] == v, f"frame {k}: ascii {key} differs from binary")

size_bin = sum(os.path.getsize(os.path.join(binary_dir, f"fields_{k}.vtu")) for k in range(len(times)))
size_asc = sum(os.path.getsize(os.path.join(ascii_dir, f"fields_{k}.vtu")) for k in range(len(times)))
print(f"{len(times)} frames: sheet files {size_bin} bytes binary (zlib) against {size_asc} bytes ascii")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
