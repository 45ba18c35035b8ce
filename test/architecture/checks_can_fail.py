#!/usr/bin/env python3
"""The architecture checks must fail when the rule they guard is broken: copies the sources into a
scratch tree, breaks one rule at a time, and expects scripts/check_layers or scripts/check_sizes to exit 1
naming the offending file.

usage: checks_can_fail.py REPO
"""
import os
import shutil
import subprocess
import sys
import tempfile

CASES = [
    # (script, file to edit, text appended, words the report must contain)
    ("check_layers", "src/core/BondFamily.hpp", '\n#include "model/Model.hpp"\n', ["src/core/BondFamily.hpp", "core includes model"]),
    ("check_layers", "materials/OsbKernels.cpp", '\n#include "solvers/Solver.hpp"\n', ["materials/OsbKernels.cpp", "materials includes solvers"]),
    ("check_layers", "src/discretization/NodeSets.cpp", "\n#include <Teuchos_ParameterList.hpp>\n", ["NodeSets.cpp", "Teuchos"]),
    ("check_layers", "src/model/Model.hpp", "\n#include <Epetra_Map.h>\n", ["src/model/Model.hpp", "Epetra"]),
    # Issue 20: the retired stack is refused in the NOX adapter too; Tpetra's stays behind its adapters.
    ("check_layers", "src/solvers/KrylovSolver.cpp", "\n#include <AztecOO.h>\n", ["KrylovSolver.cpp", "retired"]),
    ("check_layers", "src/model/Model.cpp", "\n#include <Tpetra_Map.hpp>\n", ["src/model/Model.cpp", "Tpetra"]),
    ("check_layers", "src/output/OutputManager.cpp", "\nstatic int r() { return MPI_COMM_WORLD == 0; }\n", ["OutputManager.cpp", "MPI_COMM_WORLD"]),
    ("check_sizes", "src/core/Words.cpp", "\nnamespace pf {\nint longOne() {\n  int s = 0;\n" + "  s += 1;\n" * 80 + "  return s;\n}\n}  // namespace pf\n",
     ["src/core/Words.cpp", "longOne", "limit 80"]),
    ("check_sizes", "src/core/Words.cpp", "\n" + "// padding\n" * 450, ["src/core/Words.cpp", "limit 450"]),
]


def main():
    repo = os.path.abspath(sys.argv[1])
    failures = 0
    for script, rel, text, words in CASES:
        with tempfile.TemporaryDirectory() as tmp:
            for top in ("src", "materials", "apps", "scripts"):
                shutil.copytree(os.path.join(repo, top), os.path.join(tmp, top))
            clean = subprocess.run([sys.executable, os.path.join(tmp, "scripts", script), tmp], capture_output=True, text=True)
            with open(os.path.join(tmp, rel), "a", encoding="utf-8") as f:
                f.write(text)
            r = subprocess.run([sys.executable, os.path.join(tmp, "scripts", script), tmp], capture_output=True, text=True)
            ok = clean.returncode == 0 and r.returncode == 1 and all(w in r.stdout for w in words)
            print(f"{'ok  ' if ok else 'FAIL'} {script} after editing {rel}: exit {clean.returncode} -> {r.returncode}")
            if not ok:
                print(r.stdout)
                failures += 1
    print(f"{len(CASES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
