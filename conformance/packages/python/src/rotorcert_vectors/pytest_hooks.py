"""The hook a test suite implements to name what the rotorcert plugin certifies."""
import pytest


@pytest.hookspec(firstresult=True)
def pytest_rotorcert_implementation(config):
    """Return the rotorcert_vectors.Implementation to certify (name, scalar, one function per ABI
    op, claimed clauses, declared preconditions and conventions). Called once, after collection,
    when pytest runs with --rotorcert-vectors; implement it in a conftest.py."""
