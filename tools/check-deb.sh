#!/usr/bin/env bash
# CI's check of the Debian package (docs/library.md): build spt_VERSION_amd64.deb from BUILD_DIR,
# install it with apt-get as a user would, run `spt --version` from the PATH, build and run
# examples/ as an outside project that finds the package where apt put it, and run
# examples/check_path.py with the system's python3, which finds the module where apt put it. The package is removed
# again at the end unless it was installed before, so the machine is left as it was.
# usage: tools/check-deb.sh [BUILD_DIR]     (as root: apt-get installs)
set -euo pipefail
BUILD=$(realpath "${1:-build}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
version=$(sed -n 's/^project(spt VERSION \([0-9.]*\).*/\1/p' "$SRC/CMakeLists.txt")
deb=$BUILD/spt_${version}_amd64.deb
work=$(mktemp -d)
was_installed=$(dpkg-query -W -f='${Status}' spt 2>/dev/null | grep -c 'install ok installed' || true)
cleanup() {
  rm -rf "$work"
  if [[ $was_installed == 0 ]]; then apt-get remove -y -q spt > /dev/null 2>&1 || true; fi
}
trap cleanup EXIT

rm -f "$BUILD"/spt_*.deb
(cd "$BUILD" && cpack -G DEB > "$work/cpack.log") || { cat "$work/cpack.log"; exit 1; }
[[ -f $deb ]] || { echo "check-deb: cpack made no $deb" >&2; ls "$BUILD"/*.deb >&2 || true; exit 1; }
echo "check-deb: $(basename "$deb"): $(dpkg-deb -f "$deb" Depends)"
# Everything the issue lists is in the package. The listing is read whole first: grep -q stops at
# its first match, and under pipefail the listing's SIGPIPE would fail the check.
dpkg-deb -c "$deb" | awk '{ print $6 }' > "$work/contents.txt"
for f in ./usr/bin/spt ./usr/bin/spt-editor ./usr/bin/spt-viewer ./usr/include/spt/spt.hpp \
         ./usr/lib/cmake/spt/sptConfig.cmake ./usr/share/applications/spt-editor.desktop \
         ./usr/share/applications/spt-viewer.desktop ./usr/share/icons/hicolor/scalable/apps/spt-editor.svg \
         ./usr/share/doc/spt/README.md; do
  grep -qx "$f" "$work/contents.txt" || { echo "check-deb: $f is not in the package" >&2; exit 1; }
done
grep -qE '^\./usr/lib/python3[.0-9]*/dist-packages/spt\.cpython-[^/]*\.so$' "$work/contents.txt" ||
  { echo "check-deb: the Python module is not in the package" >&2; exit 1; }
apt-get install -y -q "$deb" > "$work/apt.log" 2>&1 || { cat "$work/apt.log"; exit 1; }
got=$(cd / && spt --version)
[[ $got == "spt $version" ]] || { echo "check-deb: spt --version said '$got'" >&2; exit 1; }
# An outside project, as a user builds it: no prefix given, the package is found under /usr.
cmake -S "$SRC/examples" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release > "$work/cfg.log" 2>&1 ||
  { cat "$work/cfg.log"; exit 1; }
grep -q "spt_DIR:PATH=/usr/lib/cmake/spt" "$work/build/CMakeCache.txt" ||
  { echo "check-deb: the examples did not find the installed package" >&2; grep spt_DIR "$work/build/CMakeCache.txt" >&2; exit 1; }
cmake --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/build/convert_and_print" "$SRC/resources/meshes/figure.obj" "$work/figure.spt" > /dev/null
"$work/build/query_two_trees" "$work/figure.spt" "$work/figure.spt" 0.05 0 0 1 0 0 0 1 0 0 > "$work/query.txt"
grep -q "any: collide" "$work/query.txt" ||
  { echo "check-deb: the example's query did not find the overlap" >&2; exit 1; }
desktop-file-validate /usr/share/applications/spt-editor.desktop /usr/share/applications/spt-viewer.desktop
# The module from the package, not from a build: no PYTHONPATH, the system's python3, from /.
got=$(cd / && env -u PYTHONPATH /usr/bin/python3 -c 'import spt; print(spt.__version__)')
[[ $got == "$version" ]] || { echo "check-deb: import spt gave version '$got'" >&2; exit 1; }
(cd / && env -u PYTHONPATH /usr/bin/python3 "$SRC/examples/check_path.py" --steps 20) > "$work/path.txt"
grep -q "first contact: pose" "$work/path.txt" ||
  { echo "check-deb: examples/check_path.py did not report the path's contact" >&2; cat "$work/path.txt" >&2; exit 1; }
echo "check-deb: installed $(basename "$deb"), spt --version, an outside find_package(spt) project and import spt work"
