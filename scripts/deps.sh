#!/usr/bin/env bash
# Install what mechmat needs and is missing; quick when everything is there.
# scripts/deps.sh --test adds what only the tests need (Octave, nginx);
# scripts/deps.sh --ref what only `make ref` needs (python3-mpmath).
# Debian packages through apt-get (as root, or with sudo), browser-side
# packages through npm from the committed package-lock.json.
set -euo pipefail
cd "$(dirname "$0")/.."

debs=(
  gcc g++ make pkg-config
  libmicrohttpd-dev libcjson-dev liblapacke-dev libopenblas-serial-dev
  libfftw3-dev libmuparser-dev libcmark-dev libfmt-dev
  zlib1g-dev libdeflate-dev nettle-dev
  libcmocka-dev libcurl4-openssl-dev curl
  libgsl-dev wrk valgrind
  chromium
)
# only for `make test`: the Octave scripts' test, nginx in front of two instances
if [[ "${1:-}" == "--test" ]]; then
  debs+=(octave nginx)
fi
# only for `make ref`: the reference harness's 60-digit arithmetic (tests/ref)
# (an mpmath python3 already imports, from pip or elsewhere, is as good)
if [[ "${1:-}" == "--ref" ]]; then
  debs+=(python3)
  python3 -c 'import mpmath' 2>/dev/null || debs+=(python3-mpmath)
fi

missing=()
for p in "${debs[@]}"; do
  st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$st" == "install ok installed" ]] || missing+=("$p")
done

# Node.js may come from Debian or from elsewhere (it bundles npm then):
# ask for Debian's only when there is no node at all.
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm  >/dev/null 2>&1 || missing+=(npm)

if ((${#missing[@]})); then
  echo "deps: installing ${missing[*]}"
  SUDO=""
  [[ $(id -u) -eq 0 ]] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# npm: reinstall only when the lock file is newer than the installed tree.
if [[ -f package-lock.json ]]; then
  if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
    echo "deps: npm ci"
    npm ci --no-audit --no-fund --loglevel=error
  fi
fi
