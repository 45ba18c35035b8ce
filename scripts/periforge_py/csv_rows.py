"""A CSV with '#' comment lines (the stored histories and FE references) as rows of floats keyed by column."""
import csv


def float_rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(line for line in f if line[0] != "#")]
