# Sourced by the run.sh cases that run for real (cases/G_run_short_shear.cases) in their
# temporary folder: a copy of what run.sh uses (run.sh, tools/, scripts/, python/,
# examples/biaxial/) from ${repo}, with tools/install-deps.sh a no-op and tools/build.sh
# linking build/app/liggghts-membrane to ${exe}: nothing is installed or built, and the
# outputs go to this folder's out/.
cp "${repo}/run.sh" .
mkdir -p tools examples build/app
cp "${repo}/tools/run_options.sh" tools/
cp -r "${repo}/scripts" "${repo}/python" .
cp -r "${repo}/examples/biaxial" examples/
rm -rf examples/biaxial/out scripts/__pycache__
find python -name __pycache__ -prune -exec rm -rf {} +
printf '#!/bin/sh\nexit 0\n' > tools/install-deps.sh
printf '#!/bin/sh\nln -sfn "%s" build/app/liggghts-membrane\n' "${exe}" > tools/build.sh
chmod +x tools/install-deps.sh tools/build.sh
