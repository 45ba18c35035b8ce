"""Reading CalculiX (ccx 2.20) and gmsh (2.2 ASCII) files for the FE reference scripts (scripts/plane_j2_fe_reference,
scripts/plate_fe_reference, scripts/beam_fe_reference): the 8-node quads of a mesh, the .dat's total reaction, PEEQ
and EVOL per increment, the .frd's nodal blocks, the von Mises stress of a nodal stress row; and the J2 material
cards of linear hardening."""
import math
import re



def read_msh(path):
    """Nodes {id: (x, y)} and 8-node quads [[ids]] of a gmsh 2.2 ASCII file (type 16 = 8-node quad)."""
    nodes, quads = {}, []
    with open(path) as f:
        lines = f.read().split("\n")
    i = lines.index("$Nodes")
    n = int(lines[i + 1])
    for k in range(n):
        p = lines[i + 2 + k].split()
        nodes[int(p[0])] = (float(p[1]), float(p[2]))
    i = lines.index("$Elements")
    n = int(lines[i + 1])
    for k in range(n):
        p = list(map(int, lines[i + 2 + k].split()))
        if p[1] == 16:
            quads.append(p[3 + p[2]:])
        elif p[1] in (9, 2, 3):
            raise SystemExit("ccx reader: gmsh left a non-quad face element (type %d)" % p[1])
    return nodes, quads


def read_dat(path):
    """Per increment (time): the printed node set's total reaction, "rf" its y component and "rf_xyz" all three,
    {elem: [peeq per Gauss point]}, {elem: volume}."""
    out = []
    mode, cur = None, None
    for line in open(path):
        s = line.strip()
        m = re.search(r"and time\s+([0-9.Ee+-]+)", s)
        if m:
            t = float(m.group(1))
            if cur is None or abs(cur["t"] - t) > 1e-12:
                cur = {"t": t, "rf": None, "peeq": {}, "vol": {}}
                out.append(cur)
            mode = "rf" if s.startswith("total force") else "peeq" if s.startswith("equivalent plastic") else \
                "vol" if s.startswith("volume") else None
            continue
        if not s or mode is None:
            continue
        p = s.split()
        if mode == "rf":
            cur["rf"] = float(p[1])
            cur["rf_xyz"] = [float(v) for v in p[:3]]
            mode = None
        elif mode == "peeq":
            cur["peeq"].setdefault(int(p[0]), []).append(float(p[2]))
        elif mode == "vol":
            cur["vol"][int(p[0])] = float(p[1])
    return out


def read_frd(path):
    """Nodal blocks per increment: list of {'DISP': {node: (ux, uy)}, 'STRESS': {node: (sxx,syy,szz,sxy)},
    'PE': {node: peeq}} in increment order."""
    incs, cur, block = [], None, None
    for line in open(path):
        if line.startswith("    1PSTEP"):
            cur = {}
            incs.append(cur)
            continue
        if line.startswith(" -4"):
            block = line.split()[1]
            cur[block] = {}
            continue
        if line.startswith(" -3"):
            block = None
            continue
        if block and line.startswith(" -1"):
            node = int(line[3:13])
            v = [float(line[13 + 12 * k:25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
            cur[block][node] = v
    # the nodal blocks of one increment are spread over several 1PSTEP headers: merge consecutive ones
    merged = []
    for d in incs:
        if merged and not (set(d) & set(merged[-1])):
            merged[-1].update(d)
        else:
            merged.append(d)
    return merged


def von_mises(s):
    sxx, syy, szz, sxy = s[0], s[1], s[2], s[3]
    return math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy ** 2)


def j2_material(e, nu, sy, mod, hardening):
    """ccx cards of material J2, linear hardening of modulus mod: *PLASTIC tables are (von Mises stress, equivalent
    plastic strain) pairs; iso, kin (HARDENING=KINEMATIC) or mixed (COMBINED + *CYCLIC HARDENING, both mod)."""
    table = "%.9g,0.0\n%.9g,1.0\n" % (sy, sy + mod)
    head = "*MATERIAL, NAME=J2\n*ELASTIC\n%.9g,%.9g\n" % (e, nu)
    if hardening == "iso":
        return head + "*PLASTIC\n" + table
    if hardening == "kin":
        return head + "*PLASTIC, HARDENING=KINEMATIC\n" + table
    return head + "*PLASTIC, HARDENING=COMBINED\n" + table + "*CYCLIC HARDENING\n" + table
