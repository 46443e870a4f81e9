"""Parametric studies of the wall model: record suites (`suites`), the run grid (`grid`), one run
on the exact engine (`engine_task`, the default) or through fmi2sim (`fmi2sim_task`), the rows
they make (`rows`), running a plan on Dask (`execute`), the results file (`store`, `lock`,
`provenance`), fragility fits (`fragility`) and the IDA plots (`ida`). The command lines are
`rockingwall sweep` and `rockingwall ida`."""
