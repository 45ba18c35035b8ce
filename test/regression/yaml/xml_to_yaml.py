#!/usr/bin/env python3
"""Writes the YAML form (Teuchos' layout: a top-level ANONYMOUS map) of a Peridigm XML deck, keeping each
parameter's type: doubles as floats, ints as ints, bools as true/false, strings quoted.

usage: xml_to_yaml.py DECK.xml OUT.yaml
"""
import json
import sys
import xml.etree.ElementTree as ET


def scalar(p):
    t, v = p.get("type"), p.get("value")
    if t == "double":
        f = float(v)
        return repr(f) if ("." in repr(f) or "e" in repr(f) or "inf" in repr(f)) else repr(f) + ".0"
    if t == "int":
        return str(int(v))
    if t == "bool":
        return "true" if v.strip().lower() in ("true", "1") else "false"
    return json.dumps(v)  # a double-quoted YAML string


def emit(node, indent, out):
    for child in node:
        name = json.dumps(child.get("name"))
        if child.tag == "ParameterList":
            out.append(" " * indent + name + ":")
            if len(child) == 0:
                out[-1] += " {}"
            emit(child, indent + 2, out)
        elif child.tag == "Parameter":
            out.append(" " * indent + name + ": " + scalar(child))


def main():
    root = ET.parse(sys.argv[1]).getroot()
    out = ["%YAML 1.1", "---", "ANONYMOUS:"]
    emit(root, 2, out)
    out.append("...")
    open(sys.argv[2], "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
