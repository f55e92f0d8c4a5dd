#!/bin/sh
# The package on a fresh Debian 12 (doc/install.md, "How it is tested"): debootstrap a
# minimal bookworm into a temporary folder, install the .deb there with apt (which
# fetches every dependency it declares from the Debian mirror), and run the installed
# example and report as doc/install.md shows them, at a small scale. Needs root and the
# network (about 200 MB of packages); not part of ./test.sh for that reason.
#
#   tools/fresh_install_check.sh build/liggghts-membrane_<version>_amd64.deb [MIRROR]
set -eu
DEB=$(readlink -f "$1")
MIRROR=${2:-http://deb.debian.org/debian}
command -v debootstrap >/dev/null || apt-get install -y debootstrap
ROOT=$(mktemp -d)
cleanup() {
  for m in dev/pts dev sys proc; do umount "$ROOT/$m" 2>/dev/null || true; done
  rm -rf "$ROOT"
}
trap cleanup EXIT

debootstrap --variant=minbase bookworm "$ROOT" "$MIRROR"
mount --bind /proc "$ROOT/proc"
mount --bind /sys "$ROOT/sys"      # hwloc (Open MPI) reads the CPU topology there
mount --bind /dev "$ROOT/dev"
mount --bind /dev/pts "$ROOT/dev/pts"
cp "$DEB" "$ROOT/"
chroot "$ROOT" sh -eu -c "
  apt-get update -q
  cd / && apt-get install -y -q --no-install-recommends ./$(basename "$DEB")
  W=\$(mktemp -d)
  cd /usr/share/liggghts-membrane/examples/biaxial
  M='mpirun --allow-run-as-root --oversubscribe -np 2'
  liggghts-membrane-sample --scale 0.15 --seed 7 --out \$W/sample.data
  \$M liggghts-membrane -in in.prepare -var data \$W/sample.data -var out \$W/prepared.restart -log none > \$W/prepare.log
  \$M liggghts-membrane -in in.shear_membrane -var restart \$W/prepared.restart \
      -var eatarget 0.004 -var out \$W/membrane.txt -log none > \$W/membrane.log
  liggghts-membrane-report \$W/membrane.txt --outdir \$W/report > \$W/report.log
  head -6 \$W/report.log
  grep -q 'SHEAR done' \$W/membrane.log
  test -s \$W/report/stress_strain.png
"
echo "fresh Debian 12: the package installed with apt and ran the example"
