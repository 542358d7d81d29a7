"""One benchmark module per chapter, run by ``make bench`` after the foundation's.

Each module ``bench_<topic>.py`` here defines ``run(quick: bool) -> None``, which times its
cases with :func:`vibration.publishing.bench.median_time` and prints them with
:func:`vibration.publishing.bench.table` (ratios measured side by side in the same run).
"""
