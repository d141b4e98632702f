#!/usr/bin/env bash
# Fresh machine to first result: set up, build, run the default named case.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
build/bin/flexmoor run "${1:-ex8-relaxation-test}"   # results, summary and figure in results/<case>/
