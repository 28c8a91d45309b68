#!/usr/bin/env bash
# `make lab` as a student would start it, headless: it starts (as root too), serves the first
# chapter on a free port within a bounded wait, and stops; an unknown option in LAB_ARGS ends
# at once with Jupyter's own message and a non-zero exit, not a hang.
set -euo pipefail
cd "$(dirname "$0")/.."

WAIT=${LAB_WAIT:-300}   # seconds; the first `make lab` also installs JupyterLab into .venv
py() { python3 -c "$@"; }
port=$(py 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
token=$(py 'import secrets; print(secrets.token_hex(16))')
chapter=$(grep -m1 -o 'notebooks/[A-Za-z0-9_]*' _toc.yml | sed 's|notebooks/||').ipynb
log=$(mktemp)

# Answers 0 when GET http://127.0.0.1:$port/$1 (with the token) returns 200.
answers() {
  py "import sys, urllib.request
try:
    urllib.request.urlopen('http://127.0.0.1:$port/$1?token=$token', timeout=5)
except Exception:
    sys.exit(1)"
}

setsid make lab LAB_ARGS="--no-browser --ip=127.0.0.1 --port=$port --port-retries=0 \
  --IdentityProvider.token=$token" >"$log" 2>&1 &
lab=$!
stop() { kill -TERM -- "-$lab" 2>/dev/null || true; }
trap 'stop; rm -f "$log"' EXIT

start=$SECONDS
until answers api/status; do
  if ! kill -0 "$lab" 2>/dev/null; then
    cat "$log"; echo "check_lab: make lab exited before its server answered" >&2; exit 1
  fi
  if (( SECONDS - start > WAIT )); then
    cat "$log"; echo "check_lab: no answer on port $port within $WAIT s" >&2; exit 1
  fi
  sleep 1
done
echo "check_lab: make lab answered on port $port after $((SECONDS - start)) s"
answers "api/contents/$chapter" || { cat "$log"; echo "check_lab: $chapter not served" >&2; exit 1; }
# the page a browser is sent to (the server writes it even with --no-browser)
runtime=$(.venv/bin/jupyter --runtime-dir)
grep -qs ":$port/lab/tree/$chapter" "$runtime"/jpserver-*open.html || {
  cat "$log" "$runtime"/jpserver-*open.html; echo "check_lab: not opened on $chapter" >&2; exit 1; }
echo "check_lab: it serves notebooks/ and opens on $chapter"

stop
for _ in $(seq 30); do kill -0 "$lab" 2>/dev/null || break; sleep 1; done
if kill -0 "$lab" 2>/dev/null; then echo "check_lab: make lab did not stop" >&2; exit 1; fi
echo "check_lab: stopped"

# An unknown option: Jupyter's own message and a non-zero exit, well before the timeout.
set +e
out=$(timeout 120 make lab LAB_ARGS="--no-such-option" 2>&1)
status=$?
set -e
if (( status == 0 || status == 124 )) || ! grep -q "unrecognized arguments: --no-such-option" <<<"$out"; then
  echo "$out"; echo "check_lab: an unknown option gave exit $status" >&2; exit 1
fi
echo "check_lab: an unknown option fails at once (exit $status): $(grep -m1 unrecognized <<<"$out")"
