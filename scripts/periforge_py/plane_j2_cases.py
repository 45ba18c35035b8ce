"""The two examples of Asgari & Kouchakzadeh (2023, seed 002, "An improved plane strain/plane stress peridynamic
formulation ... von Mises materials", Sec. 5): a grooved plate specimen in plane strain and a perforated plate in
plane stress, both in uniform tension. The one place that holds their geometry, material and loading: the FE
reference (scripts/plane_j2_fe_reference), the deck generator (examples/*/make_decks.py) and the validation
(scripts/validate_plane_j2) read them from here.

The seed text is the article's preview: its Sec. 5 (dimensions, constants, loads) is not in it, only the figure
list, the abstract and the appendices. What is chosen here, and why (examples/*/README.md repeat it):
- the perforated plate is the classical perforated strip of plane-stress elastoplasticity (Zienkiewicz, Valliappan
  & King 1969; Owen & Hinton, "Finite Elements in Plasticity", 1980): 36 mm long, 20 mm wide, a central hole of
  radius 5 mm, E = 70 GPa, nu = 0.2, sigma_y = 243 MPa, linear isotropic hardening H' = 2.24 GPa;
- the grooved plate is the same strip with two semicircular edge grooves of radius 5 mm at mid-length instead of
  the hole (the same 10 mm net ligament), in plane strain, with the same material: the two cases then differ only
  in the notch and in the planar assumption;
- loading along the length (y, "vertical" as in the paper's Fig. 13: "vertical central axis displacement",
  "horizontal central axis von Mises stress"), displacement-controlled through the ends: the bottom end held in y,
  the top end moved by u(t) in y, both ends free in x (FE: edge nodes; PD: fictitious layers one horizon deep),
  monotonic to U_MAX in N_STEPS equal steps -- well past general yield of the ligament, so the curve shows the
  elastic range, contained and then uncontained plasticity;
- thickness 1 mm (the plane-strain force is per 1 mm of depth).
SI units. Coordinates: the PD plate spans x in [0, W], y in [0, L]; the notch centre at (W/2, L/2).
"""
import math

E = 70.0e9
NU = 0.2
SIGMA_Y = 243.0e6
K_ISO = 2.24e9          # linear isotropic hardening: sigma_y(peeq) = SIGMA_Y + K_ISO * peeq
THICKNESS = 1.0e-3
L = 36.0e-3             # length, along the load (y)
W = 20.0e-3             # width (x)
R = 5.0e-3              # hole / groove radius
N_STEPS = 40

CASES = {
    # name: planar assumption, notch, end displacement at the last step
    "grooved_plate": {"plane": "strain", "notch": "grooves", "u_max": 0.15e-3},
    "perforated_plate": {"plane": "stress", "notch": "hole", "u_max": 0.15e-3},
}


def case(name):
    if name not in CASES:
        raise SystemExit("unknown case %r (known: %s)" % (name, ", ".join(CASES)))
    return CASES[name]


def applied(step, name):
    """End displacement at load step `step` (0..N_STEPS)."""
    return case(name)["u_max"] * step / N_STEPS


def inside_notch(x, y, name):
    """True if (x, y) in the PD frame is removed by the notch (the circle itself is kept)."""
    cx = W / 2
    if case(name)["notch"] == "hole":
        return math.hypot(x - cx, y - L / 2) < R * (1 - 1e-12)
    return min(math.hypot(x, y - L / 2), math.hypot(x - W, y - L / 2)) < R * (1 - 1e-12)


def gross_area():
    return W * L


def net_area(name):
    """Plate area minus the notch (a full circle for the hole, two half circles for the grooves)."""
    return W * L - math.pi * R * R
