"""Display units for Periforge's output names, shared by plot_history and plot_field: SI values from
the files are shown in the units engineers read (mm, kN, MPa). Not an executable."""

# (substring of the name, factor from SI, unit); the first match wins, so specific names come first.
_UNITS = [
    ("Plastic_Strain_Rate", 1.0, "1/s"),
    ("Plastic_Strain", 1.0, "-"),
    ("Plastic_Extension", 1e3, "mm"),
    ("Dilatation", 1.0, "-"),
    ("Temperature", 1.0, "K"),
    ("Flux_Divergence", 1.0, "W/m^3"),
    ("Damage", 1.0, "-"),
    ("Lambda", 1.0, "-"),
    ("Stress", 1e-6, "MPa"),
    ("Reaction", 1e-3, "kN"),
    ("Force_Density", 1e-9, "GN/m^3"),
    ("Displacement", 1e3, "mm"),
    ("Velocity", 1.0, "m/s"),
    ("Coordinates", 1e3, "mm"),
    ("time", 1.0, "s"),
]


def unit_of(name):
    """(factor, unit) for a column or variable name; (1, '') when no unit is known."""
    for key, factor, unit in _UNITS:
        if key in name:
            return factor, unit
    return 1.0, ""


def label_of(name):
    """'Reaction_Left_X' -> 'Reaction Left X [kN]'."""
    _, unit = unit_of(name)
    text = name.replace("_", " ")
    return f"{text} [{unit}]" if unit else text
