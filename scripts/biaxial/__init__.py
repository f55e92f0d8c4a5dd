"""Post-processing of the 2D DEM biaxial tests (rigid walls vs fix membrane2d).

Modules:
    readers  -- the three files one run writes: OUT table, OUT.rose, OUT.dump
    curves   -- macro quantities from the stress-strain table (peak, E, nu, phi, psi)
    field    -- incremental displacement / shear-strain field and shear-band detection
    rose     -- polar histograms and the fitted E(theta), f_n(theta) curves
    plots    -- the PNG figures (stress_strain_band: mean over samples with its 95 % band)
    stats    -- Student-t quantile, 95 % intervals of a mean and of a paired difference
    replicates -- the table over replicate samples (mean ± interval, paired differences)
    summary  -- the rigid-vs-membrane table (Markdown and CSV)
    vtk_files -- the run's VTK polydata files read back (python3-vtk9)

Everything reported is computed from a run's files; what cannot be measured is
returned as a NotMeasurable value carrying the reason.
"""
