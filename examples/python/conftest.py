"""pytest settings for the Python examples (docs/python.md).

No Hypothesis deadline: the pure-Python solver takes milliseconds per graph,
but a loaded machine can stretch one past Hypothesis' default 200 ms, and
that is not a bug. `--hypothesis-profile=thorough` runs 10,000 examples per
property instead of 100.
"""
from hypothesis import settings

settings.register_profile("examples", deadline=None)
settings.register_profile("thorough", max_examples=10_000, deadline=None)
settings.load_profile("examples")
