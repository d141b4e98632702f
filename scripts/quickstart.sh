#!/usr/bin/env bash
# Fresh machine to first result: set up, build the flexmoor command alone (and the MPI module it
# loads under mpirun; not the test suite, which scripts/test.sh builds), run the default named case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh flexmoor
build/bin/flexmoor run "${1:-ex8-relaxation-test}"   # results, summary and figure in results/<case>/
