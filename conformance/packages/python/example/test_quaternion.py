"""The example library's own unit tests: they run beside the rotorcert items, as in any test suite."""
import math

import pytest

import quaternion


def test_compose_applies_the_right_factor_first():
    quarter_z = [0.0, 0.0, math.sqrt(0.5), math.sqrt(0.5)]  # 90 degrees about z
    quarter_x = [math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]  # 90 degrees about x
    v = quaternion.apply_vector(quaternion.compose(quarter_z, quarter_x), [0.0, 1.0, 0.0])
    assert v == pytest.approx([0.0, 0.0, 1.0], abs=1e-15)  # y -> z by x first; z stays under z


def test_zero_is_not_a_rotation():
    with pytest.raises(ValueError):
        quaternion.normalize([0.0, 0.0, 0.0, 0.0])
