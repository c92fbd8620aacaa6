"""What every algorithm family is built on.

``steps``        the closed set of records a step generator yields
``code``         pseudo-code built from named lines
``registry``     algorithm specs by name: inputs, options, pseudo-code, generator
``trace``        a generator recorded once, with random access to every step
``trace_store``  where a trace keeps its frames (numpy columns, pickled batches)
``keyframes``    the compact rasters a trace replays from
``raster``       the framebuffer state a trace replays into
``monitor``      progress, cancellation and the work a run may do
``compiled``     loops compiled with numba on first use when it is installed, plain otherwise
``errors``       the errors the families share
``cases``        the hard-case catalogue (tests and ``rasterlab check``)
"""
