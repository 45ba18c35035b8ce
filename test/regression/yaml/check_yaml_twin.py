#!/usr/bin/env python3
"""A deck written in YAML gives the answer of its XML form bit for bit: converts DECK.xml with
xml_to_yaml.py, runs it, and compares the history CSV byte by byte with the XML run's.

usage: check_yaml_twin.py PERIFORGE DECK.xml XML_RUN_CSV
"""
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
exe, deck, xml_csv = sys.argv[1:4]
with tempfile.TemporaryDirectory() as d:
    stem = os.path.splitext(os.path.basename(deck))[0]
    yaml = os.path.join(d, stem + ".yaml")
    subprocess.run([sys.executable, os.path.join(here, "xml_to_yaml.py"), deck, yaml], check=True)
    # Files the deck names relative to itself resolve against the deck's directory.
    for f in os.listdir(os.path.dirname(os.path.abspath(deck))):
        if f.endswith(".txt"):
            shutil.copy(os.path.join(os.path.dirname(os.path.abspath(deck)), f), d)
    r = subprocess.run([exe, yaml], cwd=d, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        print(r.stdout[-2000:], r.stderr[-2000:])
        sys.exit(f"FAIL: the YAML deck exited {r.returncode}")
    same = filecmp.cmp(os.path.join(d, stem + ".csv"), xml_csv, shallow=False)
    print(("PASS" if same else "FAIL") + f": {stem}.yaml history {'equals' if same else 'differs from'} the XML run's")
    sys.exit(0 if same else 1)
