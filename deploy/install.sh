#!/usr/bin/env bash
# deploy/install.sh DESTDIR PREFIX SERVER_BIN — what `make install` runs.
#
# Installs everything the server needs at run time, and nothing else:
#   PREFIX/bin/mechmat-server
#   PREFIX/share/mechmat/web/             the pages, __MM_ASSET_VERSION__ replaced
#                                         by the asset version, which is also
#                                         written to web/.asset-version (so that
#                                         nginx serving these files and the server
#                                         agree on ?v=)
#   PREFIX/share/mechmat/exercises/       theory texts (*.md) and script bodies (*.m)
#   PREFIX/share/mechmat/node_modules/    the browser packages (package.json, dist/)
#   PREFIX/share/mechmat/deploy/          nginx and systemd files, an example course
# The installed binary finds PREFIX/share/mechmat by itself (main.c).
set -euo pipefail
cd "$(dirname "$0")/.."
destdir=${1:-}
prefix=${2:-/usr/local}
bin=${3:-build/mechmat-server}
share="$destdir$prefix/share/mechmat"
packages=(katex)                 # package.json "dependencies" (d3 and Plot went in deb6ec1)

[[ -x "$bin" ]] || { echo "install: $bin is not built (make first)"; exit 1; }
for p in "${packages[@]}"; do
  [[ -f "node_modules/$p/package.json" ]] || { echo "install: node_modules/$p is missing (make deps)"; exit 1; }
done
version=$("$bin" --root . --print-asset-version)
echo "install: into $destdir$prefix (asset version $version)"

install -d "$destdir$prefix/bin" "$share"
install -m 755 "$bin" "$destdir$prefix/bin/mechmat-server"

rm -rf "$share/web" "$share/exercises" "$share/node_modules" "$share/deploy"
# web/: text files with the version in place
# (not the developers' notes, web/**/*.md: they are no page, and they name
# the version token in their text)
(cd web && find . -type f ! -name '.*' ! -name '*.md' -print0) | while IFS= read -r -d '' f; do
  install -d "$share/web/$(dirname "$f")"
  case "$f" in
    *.html|*.js|*.mjs|*.css) sed "s/__MM_ASSET_VERSION__/$version/g" "web/$f" > "$share/web/$f"
                              chmod 644 "$share/web/$f" ;;
    *) install -m 644 "web/$f" "$share/web/$f" ;;
  esac
done
printf '%s\n' "$version" > "$share/web/.asset-version"

(find exercises -type f \( -name '*.md' -o -name '*.m' \) -print0) | while IFS= read -r -d '' f; do
  install -d "$share/$(dirname "$f")"
  install -m 644 "$f" "$share/$f"
done

for p in "${packages[@]}"; do
  install -d "$share/node_modules/$p"
  install -m 644 "node_modules/$p/package.json" "$share/node_modules/$p/package.json"
  cp -R "node_modules/$p/dist" "$share/node_modules/$p/dist"
done
chmod -R u=rwX,go=rX "$share/node_modules"

# a compressed copy beside each text file, for nginx's gzip_static (made
# once here instead of on every request)
find "$share/web" "$share/node_modules" -type f \( -name '*.js' -o -name '*.mjs' -o -name '*.css' \
     -o -name '*.html' -o -name '*.svg' -o -name '*.json' -o -name '*.ttf' \) -size +1k -print0 |
  xargs -0 -r gzip -9 -n -k -f

install -d "$share/deploy/nginx" "$share/deploy/systemd"
install -m 644 deploy/nginx/mechmat.conf "$share/deploy/nginx/"
install -m 644 deploy/systemd/mechmat.service deploy/systemd/mechmat@.service "$share/deploy/systemd/"
install -m 644 deploy/course.example.json "$share/deploy/"
echo "install: done; try: $prefix/bin/mechmat-server --port 8080"
