#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the .deb with cpack from a configured and built tree, then checks that it installs
# both programs, the desktop file, the icon, the AppStream metainfo and the examples, and that
# the desktop file and metainfo pass their validators, and that it depends on and recommends the
# packages Qt's plugins, the solid check and the translations need (dpkg-shlibdeps cannot see them).
set -eu
build_dir=$1
source_dir=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

(cd "$build_dir" && cpack -G DEB -B "$out" >"$out/cpack.log" 2>&1) || { cat "$out/cpack.log"; exit 1; }
deb=$(ls "$out"/tolturn_*.deb)
dpkg-deb -c "$deb" >"$out/contents"
status=0
for path in ./usr/bin/tolturn ./usr/bin/tolturn-cli \
    ./usr/share/applications/org.tolturn.TolTurn.desktop \
    ./usr/share/icons/hicolor/scalable/apps/org.tolturn.TolTurn.svg \
    ./usr/share/metainfo/org.tolturn.TolTurn.metainfo.xml \
    ./usr/share/mime/packages/tolturn.xml \
    ./usr/share/tolturn/examples/stepped-shaft-chuck.tolturn \
    ./usr/share/doc/tolturn/user-guide/index.html \
    ./usr/share/doc/tolturn/user-guide/planning.html; do
    if ! grep -q " $path\$" "$out/contents"; then
        echo "missing from package: $path"
        status=1
    fi
done
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
case "$depends" in
*libqt6widgets6*) ;;
*) echo "Depends lacks libqt6widgets6 (dpkg-shlibdeps did not run?)"; status=1 ;;
esac
recommends=$(dpkg-deb -f "$deb" Recommends)
echo "Recommends: $recommends"
for wanted in libqt6sql6-psql gmsh calculix-ccx qt6-translations-l10n; do
    case ", $recommends," in
    *", $wanted,"*) ;;
    *) echo "Recommends lacks $wanted"; status=1 ;;
    esac
done
desktop-file-validate "$source_dir/packaging/linux/org.tolturn.TolTurn.desktop"
appstreamcli validate --no-net --pedantic "$source_dir/packaging/linux/org.tolturn.TolTurn.metainfo.xml" || {
    # pedantic findings are printed; only errors and warnings fail the check
    appstreamcli validate --no-net "$source_dir/packaging/linux/org.tolturn.TolTurn.metainfo.xml"
}
exit $status
