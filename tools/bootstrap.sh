#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs everything TolTurn needs to build and test on Debian 12, from the one list of build
# dependencies: packaging/debian/control (Build-Depends). Does nothing when all are present.
# Runs as root, or through sudo for another user.
set -eu
cd "$(dirname "$0")/.."

if [ "$(id -u)" -eq 0 ]; then
    as_root=""
elif command -v sudo >/dev/null 2>&1; then
    as_root="sudo"
else
    echo "bootstrap: installing packages needs root; run as root or install sudo" >&2
    exit 1
fi

if command -v dpkg-checkbuilddeps >/dev/null 2>&1 && (cd packaging && dpkg-checkbuilddeps) 2>/dev/null; then
    echo "bootstrap: all build dependencies are installed"
    exit 0
fi

echo "bootstrap: installing the build dependencies of packaging/debian/control"
export DEBIAN_FRONTEND=noninteractive
$as_root apt-get update
$as_root apt-get install -y --no-install-recommends ca-certificates dpkg-dev
$as_root apt-get build-dep -y --no-install-recommends ./packaging
