# SPDX-License-Identifier: MIT
"""A pendulum built from Python keeps its exact period.

A rigid body turning about a fixed pivot, its centre of mass at d from it,
obeys I_p·θ'' = -m·g·d·sin θ; released from rest at θ0 it swings with the
period T = 4·sqrt(I_p/(m·g·d))·K(k), k = sin(θ0/2), K the complete
elliptic integral of the first kind. K is computed here independently of
the engine and of GSL, by the arithmetic-geometric mean (Gauss):
K(k) = π / (2·AGM(1, sqrt(1 - k²))).

The engine integrates with semi-implicit Euler, whose period error with
substeps of h is (ω·h)²/24, about 1e-6 here (the C suite,
tests/test_pendulum.c, derives it): the tolerances are theirs, 1e-4 at
small amplitude and 2e-3 at large ones.
"""
import math

import pytest

import sinew

G = 9.8


def agm(a, b):
    """The arithmetic-geometric mean of a and b. It converges quadratically
    (the digits double each step): 8 steps reach the last bit from
    b/a = 0.13 (θ0 = 165°), and the loop stops once the two means agree
    or cycle within an ulp."""
    for _ in range(32):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        if abs(a - b) <= 4e-16 * a:
            break
    return a


def elliptic_k(k):
    """K(k), modulus k (not the parameter k²)."""
    return math.pi / (2.0 * agm(1.0, math.sqrt(1.0 - k * k)))


def exact_period(pivot_inertia, mass, distance, theta0):
    return 4.0 * math.sqrt(pivot_inertia / (mass * G * distance)) * elliptic_k(math.sin(0.5 * theta0))


def test_agm_gives_known_values():
    # K(0) = π/2; K(sin 45°) = Γ(1/4)²/(4·sqrt(π)) (Legendre), 1.8540746773013719.
    assert elliptic_k(0.0) == pytest.approx(math.pi / 2, rel=1e-15)
    assert elliptic_k(math.sqrt(0.5)) == pytest.approx(math.gamma(0.25) ** 2 / (4 * math.sqrt(math.pi)), rel=1e-14)


def measure_period(world, bob, dt, half_periods, expected):
    """Twice the time between the first and the last of half_periods + 1
    zero crossings of θ, each placed by linear interpolation."""

    def theta():
        c = bob.world_center
        return math.atan2(c.x, -c.y)

    previous, first, last, crossings = theta(), 0.0, 0.0, 0
    for n in range(1, math.ceil((half_periods + 1) * expected / dt) + 1):
        world.step(dt)
        now = theta()
        if (previous > 0.0) != (now > 0.0):
            t = (n - 1) * dt + dt * previous / (previous - now)
            first = t if crossings == 0 else first
            last = t
            crossings += 1
            if crossings > half_periods:
                break
        previous = now
    assert crossings == half_periods + 1
    return 2.0 * (last - first) / half_periods


@pytest.mark.parametrize("degrees, tolerance", [(5.0, 1e-4), (90.0, 2e-3), (150.0, 2e-3)])
def test_simple_pendulum_keeps_its_exact_period(degrees, tolerance):
    length, radius, density = 1.0, 0.05, 100.0
    theta0 = math.radians(degrees)
    with sinew.World(gravity=(0.0, -G)) as world:
        ground = world.create_body("static")
        bob = world.create_body(
            "dynamic", position=(length * math.sin(theta0), -length * math.cos(theta0)), angle=theta0
        )
        bob.add_circle(radius, density=density)
        world.create_revolute_joint(ground, bob, (0.0, 0.0))
        m = density * math.pi * radius**2
        assert bob.mass == pytest.approx(m, rel=1e-12)
        exact = exact_period(0.5 * m * radius**2 + m * length**2, m, length, theta0)
        measured = measure_period(world, bob, 1.0 / 240.0, 10, exact)
        assert abs(measured - exact) <= tolerance * exact, (measured, exact)


def test_compound_rod_keeps_its_exact_period():
    """A box rod of length ℓ pivoted at the middle of one end:
    I_p = m·(ℓ² + w²)/12 + m·(ℓ/2)²."""
    length, width, density = 1.0, 0.05, 1.0
    theta0 = math.radians(30.0)
    with sinew.World(gravity=(0.0, -G)) as world:
        ground = world.create_body("static")
        d = 0.5 * length
        rod = world.create_body("dynamic", position=(d * math.sin(theta0), -d * math.cos(theta0)), angle=theta0)
        rod.add_box(0.5 * width, 0.5 * length, density=density)
        world.create_revolute_joint(ground, rod, (0.0, 0.0))
        m = density * length * width
        inertia = m * (length**2 + width**2) / 12.0 + m * d * d
        assert rod.rotational_inertia + m * d * d == pytest.approx(inertia, rel=1e-12)
        exact = exact_period(inertia, m, d, theta0)
        measured = measure_period(world, rod, 1.0 / 240.0, 10, exact)
        assert abs(measured - exact) <= 1e-4 * exact, (measured, exact)
