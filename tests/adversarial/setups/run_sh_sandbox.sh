# Sourced by the run.sh cases (cases/G_run_options.cases) in their temporary folder: a
# copy of run.sh and tools/run_options.sh from ${repo}, with tools/install-deps.sh and
# tools/build.sh replaced by stubs that print "WORK STARTED" and exit 97. A run.sh that
# checks its options first never reaches them; one that does not shows it, and nothing
# is installed, built or run.
cp "${repo}/run.sh" .
mkdir -p tools
cp "${repo}/tools/run_options.sh" tools/
for stub in install-deps.sh build.sh; do
  printf '#!/bin/sh\necho "WORK STARTED: tools/%s"\nexit 97\n' "$stub" > "tools/$stub"
  chmod +x "tools/$stub"
done
