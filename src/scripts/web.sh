#!/usr/bin/env bash
# Installs the browser viewer's dependencies and builds it into web/dist.
# Idempotent and quick when nothing changed: Node.js and npm come from Debian
# (nodejs, npm: Node 18) only when `node` is missing; `npm ci` runs only when
# package-lock.json is newer than the last install; the build only when a
# source is newer than web/dist.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
web="$root/web"

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "web: run as root to install nodejs and npm" >&2; exit 1; }
    sudo=(sudo)
  fi
  echo "web: installing nodejs and npm"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq nodejs npm >/dev/null
fi
major="$(node -p 'process.versions.node.split(".")[0]')"
if ((major < 18)); then
  echo "web: the viewer needs Node.js 18 or later, found $(node --version)" >&2
  exit 1
fi

cd "$web"
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
  echo "web: npm ci"
  npm ci --no-audit --no-fund --loglevel=error
fi
if [[ ! -f dist/index.html ]] ||
  [[ -n "$(find index.html src package.json package-lock.json vite.config.ts \
    tailwind.config.js postcss.config.js -newer dist/index.html -print -quit)" ]]; then
  echo "web: building the viewer"
  npm run --silent build -- --logLevel warn
fi
echo "web: viewer built in web/dist"
