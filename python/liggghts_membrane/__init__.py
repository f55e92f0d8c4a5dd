"""liggghts_membrane: the Python of the project (post-processing, commands, benchmarks).

Found on PYTHONPATH in a checkout (run.sh, test.sh, the example drivers and CTest put the
repository's python/ there) and in /usr/lib/python3/dist-packages when installed by the
Debian package (the installed commands put their prefix's lib/python3/dist-packages first).

One module per file format:
    readers    -- the OUT/thermo table of a run, OUT.rose, OUT.dump, OUT.params, a data file
    vtk_files  -- VTK files (.vtp XML polydata, .vtk legacy), read with python3-vtk9
    pvd        -- ParaView collections (.pvd): written (run.pvd of a folder) and read back
Analysis:
    grains     -- D50 by mass (the step definition of the C++ styles)
    curves     -- macro quantities from the stress-strain table (peak, E, nu, phi, psi)
    field      -- incremental displacement / shear-strain field and shear-band detection
    particle_strain -- the strain measured from the particles' positions
    rose       -- polar histograms and the fitted E(theta), f_n(theta) curves
    stats      -- 95 % intervals of a mean and of a paired difference (scipy.stats)
    replicates -- the table over replicate samples (mean +- interval, paired differences)
    summary    -- the rigid-vs-membrane table (Markdown and CSV)
    plots      -- the PNG figures
    params     -- the variables of the LIGGGHTS input scripts
    report     -- one run loaded for the report
    resume     -- resuming an interrupted shear (run.sh --paper)
Commands (the scripts in scripts/, examples/ and bench/ are thin entry points):
    report_command (liggghts-membrane-report), sample (liggghts-membrane-sample),
    progress, membrane_plot, render_paraview, triaxial_plot, triaxial_compare
    bench      -- the benchmark drivers of bench/ (a checkout only; not installed)
Test helpers (a checkout only; not installed):
    synthetic  -- runs with known answers; run_script -- input-script tests ('#@')

Everything reported is computed from a run's files; what cannot be measured is
returned as a NotMeasurable value carrying the reason.
"""
