"""Shared pytest configuration: hypothesis profiles.

default (`make test`): a quick pass of every property, 20 examples each; ci (`make test-all`, or CI set
in the environment): 100, reproducible; thorough: 2000. Tests that set their own count take it through
strategies.examples(n), which scales n (the ci count) with the profile.
"""

import os

from hypothesis import HealthCheck, settings

settings.register_profile("default", max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("ci", max_examples=100, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("thorough", max_examples=2000, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "default"))
