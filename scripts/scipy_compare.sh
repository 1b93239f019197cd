#!/usr/bin/env bash
# Runs scripts/scipy_compare.py with numpy and scipy available: the python3 on PATH if it has
# them, otherwise a virtual environment in target/scipy-venv (created and filled with pip), or
# `pip install --user` if venv is unavailable. Arguments are passed to the script.
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-python3}
if ! "$PY" -c 'import numpy, scipy' 2>/dev/null; then
    VENV=${SCIPY_VENV:-target/scipy-venv}
    if [ -x "$VENV/bin/python" ] || "$PY" -m venv "$VENV" 2>/dev/null; then
        "$VENV/bin/python" -c 'import numpy, scipy' 2>/dev/null \
            || "$VENV/bin/pip" install --quiet numpy scipy
        PY="$VENV/bin/python"
    else
        "$PY" -m pip install --quiet --user numpy scipy
    fi
fi
exec "$PY" scripts/scipy_compare.py "$@"
