"""Certifies quaternion.py with rotorcert from this test suite: `pytest --rotorcert-vectors DIR`."""
import quaternion
import rotorcert_vectors


def pytest_rotorcert_implementation(config):
    return rotorcert_vectors.Implementation(
        name="example_quaternion", version=quaternion.__version__, scalar="double",
        description="conformance/packages/python/example: quaternion.py in Python floats",
        ops={"normalize": quaternion.normalize, "compose": quaternion.compose, "inverse": quaternion.inverse,
             "apply_vector": quaternion.apply_vector, "slerp": quaternion.slerp},
        claimed_clauses=["QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1",
                         "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "EDGE-6", "EDGE-7"])
