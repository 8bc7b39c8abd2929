"""Runs pytest on the module's tests; exits 77 (skipped) when pytest, NumPy or matplotlib is missing."""
import sys

try:
    import matplotlib  # noqa: F401
    import numpy  # noqa: F401
    import pytest
except ImportError as e:
    print("skipped: %s (apt-get install python3-pytest python3-numpy python3-matplotlib)" % e)
    sys.exit(77)
sys.exit(pytest.main(sys.argv[1:]))
