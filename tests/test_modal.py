"""The one eigen-solver: undamped generalised problems, damped state space, MAC tracking."""

import math

import numpy as np
import pytest

from wtvib.numerics import modal


def test_two_mass_chain_against_the_closed_form():
    # free–free two masses on a spring: ω² = k(J1 + J2)/(J1·J2), plus a rigid-body 0 — to
    # within what rounding leaves of a zero ω² (ω² = 1/μ − σ: a few ε·σ) under the root
    j1, j2, k = 3.0, 1.0, 12.0
    res = modal.solve(np.array([[k, -k], [-k, k]]), np.diag([j1, j2]))
    expected = math.sqrt(k * (j1 + j2) / (j1 * j2)) / (2 * math.pi)
    zero = math.sqrt(16 * np.finfo(float).eps * modal.SHIFT) / (2 * math.pi)
    assert res.frequency_hz[0] == pytest.approx(0.0, abs=zero)
    assert res.frequency_hz[1] == pytest.approx(expected, rel=1e-12)


def test_damped_single_mode_gives_back_its_damping_ratio():
    # m q̈ + c q̇ + k q = 0 with c = 2ζ√(km): ζ and ωn = √(k/m) come back exactly
    m, k, zeta = 2.0, 800.0, 0.05
    c = 2 * zeta * math.sqrt(k * m)
    res = modal.damped(np.array([[k]]), np.array([[m]]), np.array([[c]]))
    assert res.damping_ratio == pytest.approx([zeta])
    assert res.frequency_hz == pytest.approx([math.sqrt(k / m) / (2 * math.pi)])


def test_state_matrix_broadcasts_over_stacks():
    k = np.stack([np.eye(2) * s for s in (1.0, 4.0)])
    a = modal.state_matrix(k, np.eye(2), np.zeros((2, 2)))
    assert a.shape == (2, 4, 4)
    assert np.abs(np.linalg.eigvals(a[1])).max() == pytest.approx(2.0)  # ω = √4


def test_an_unstable_drive_train_is_refused():
    with pytest.raises(modal.ModalError, match="unstable"):
        modal.damped(np.array([[1.0]]), np.array([[1.0]]), np.array([[-0.5]]))


def test_track_follows_crossing_curves_by_shape():
    a = np.eye(3)
    b = np.eye(3)[:, [2, 0, 1]]  # the same shapes, shuffled
    assert list(modal.track(a, b)) == [1, 2, 0]
    assert modal.mac(a, b)[0, 1] == pytest.approx(1.0)


def test_the_optimal_assignment_is_the_best_of_all():
    """modal.assign(optimal=True) against every assignment of rows to distinct columns."""
    import itertools

    rng = np.random.default_rng(7)
    for _ in range(200):
        n = int(rng.integers(1, 6))
        m = n + int(rng.integers(0, 4))
        score = rng.random((n, m))
        got = modal.assign(score, optimal=True)
        assert len(set(got.tolist())) == n
        best = max(
            sum(score[i, j] for i, j in enumerate(p)) for p in itertools.permutations(range(m), n)
        )
        assert score[np.arange(n), got].sum() == pytest.approx(best, abs=1e-12)


def test_deep_stacks_invert_their_cholesky_factors_row_by_row():
    """modal._inverse_lower: a stack of 2,000 lower-triangular 6 × 6 factors (the Monte
    Carlo path) inverted by vectorised forward substitution equals numpy's inverse to
    rounding; a shallow stack goes to numpy's inverse as it is."""
    import numpy as np

    from wtvib.numerics import modal

    rng = np.random.default_rng(7)
    a = rng.standard_normal((2000, 6, 6))
    lower = np.linalg.cholesky(a @ np.swapaxes(a, -1, -2) + 6 * np.eye(6))
    assert lower.shape[0] >= modal.DEEP_STACK * 6  # the row-by-row path
    got = modal._inverse_lower(lower)
    np.testing.assert_allclose(got, np.linalg.inv(lower), rtol=0, atol=1e-13)
    assert np.all(np.triu(got, 1) == 0.0)  # lower-triangular, as the inverse must be
    few = lower[:3]
    assert np.array_equal(modal._inverse_lower(few), np.linalg.inv(few))


def _chain(n: int) -> tuple[np.ndarray, np.ndarray]:
    """A fixed–free chain of n unit masses on unit springs."""
    k = 2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)
    k[-1, -1] = 1.0
    return k, np.diag(np.linspace(1.0, 2.0, n))


def test_ritz_basis_holds_the_modes_and_one_vector_per_new_load_direction():
    """M-orthonormal; the lowest modes first, as solve gives them; a change the kept modes
    carry whole (C = M: C φ = M φ) adds nothing, a spring to ground at one mass (rank one)
    exactly one vector, whatever the number of modes imaged."""
    k, m = _chain(30)
    spring = np.zeros_like(k)
    spring[7, 7] = 1.0
    modes = modal.solve(k, m, 4).shapes
    assert modal.ritz_basis(k, m, 4, [m], 4).shape[1] == 4
    basis = modal.ritz_basis(k, m, 4, [spring, m], 4)
    assert basis.shape[1] == 5
    np.testing.assert_allclose(basis.T @ m @ basis, np.eye(5), atol=1e-12)
    np.testing.assert_allclose(np.abs(basis[:, :4]), np.abs(modes), atol=1e-12)


def test_ritz_basis_follows_a_changed_problem_closer_than_its_modes_alone():
    """The lowest four frequencies of the chain with a spring to ground at one mass, from
    the unchanged modes and their one load-dependent vector: upper bounds of the full
    problem's (the reference; Rayleigh–Ritz), five times closer than the modes alone give
    them (measured 6.1e-6 against 1.3e-6). A chain's spectrum is dense: a model whose
    truncated modes lie far above the kept ones (the coupled turbine) gains orders of
    magnitude (tests/validation/test_coupled.py)."""
    k, m = _chain(30)
    spring = np.zeros_like(k)
    spring[20, 20] = 1e-3

    def lowest(basis: np.ndarray) -> np.ndarray:
        return modal.solve(basis.T @ (k + spring) @ basis, basis.T @ m @ basis, 4).frequency_hz

    exact = modal.solve(k + spring, m, 4).frequency_hz
    plain = lowest(modal.solve(k, m, 4).shapes) / exact - 1
    enriched = lowest(modal.ritz_basis(k, m, 4, [spring], 4)) / exact - 1
    assert np.all(enriched > -1e-12) and np.all(enriched <= plain + 1e-12)
    assert enriched.max() < plain.max() / 4, (plain, enriched)


def test_roots_beyond_double_precision_are_refused_not_returned():
    """Two masses, one on a spring 10³⁰ times stiffer than the other's: the slow root is
    below the eigen-solver's rounding (machine epsilon times the matrix's norm), so the
    damped solve refuses with a ModalError instead of returning rounding as a frequency;
    10⁸ times stiffer is resolved (the slow root as its closed form √k/m, to 1e-6)."""
    m = np.eye(2)
    d = np.zeros((2, 2))
    lam, _ = modal.oscillations(np.diag([1.0, 1e8]), m, d, floor=1e-3)
    assert abs(lam[0]) == pytest.approx(1.0, rel=1e-6)
    with pytest.raises(modal.ModalError, match="orders of magnitude"):
        modal.oscillations(np.diag([1.0, 1e30]), m, d, floor=1e-3)


def _same_modes(large: modal.StateModes, small: modal.StateModes) -> None:
    """The two paths' roots and participation factors equal to rounding, and their right
    eigenvectors one shape each (each to a phase of its own: MAC 1)."""
    i = np.lexsort((small.roots.imag, small.roots.real))
    j = np.lexsort((large.roots.imag, large.roots.real))
    np.testing.assert_allclose(large.roots[j], small.roots[i], rtol=1e-12)
    np.testing.assert_allclose(large.participation[:, j], small.participation[:, i], atol=1e-10)
    a, b = large.vectors[:, j], small.vectors[:, i]
    mac = np.abs(np.einsum("ki,ki->i", a.conj(), b)) ** 2
    mac /= (np.abs(a) ** 2).sum(axis=0) * (np.abs(b) ** 2).sum(axis=0)
    np.testing.assert_allclose(mac, 1.0, rtol=1e-9)


def test_state_modes_large_path_matches_the_inverse_of_the_right_vectors() -> None:
    """From LEFT_VECTORS_STATES states on, the left eigenvectors come from LAPACK with the
    right ones: the roots and participation factors equal the small path's (Φ⁻¹) to
    rounding, and a defective matrix (a Jordan block) is refused on both."""
    rng = np.random.default_rng(3)
    a = rng.normal(size=(60, 60))
    small = modal.state_modes(a)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(modal, "LEFT_VECTORS_STATES", 1)
        large = modal.state_modes(a)
        with pytest.raises(modal.ModalError, match="defective"):
            modal.state_modes(np.diag([1.0, 1.0], k=1))
    _same_modes(large, small)
    with pytest.raises(modal.ModalError, match="defective"):
        modal.state_modes(np.diag([1.0, 1.0], k=1))


def test_a_defective_complex_pair_is_refused_on_both_paths() -> None:
    """A Jordan block of an oscillating pair — λ = ±i twice, one eigenvector each:
    A = [[R, I], [0, R]], R = [[0, 1], [−1, 0]] — is refused by the small path (numpy's
    vectors, their inverse: ψᵢ of norm ~10¹⁶ where ψᵢᵀ·φᵢ = 1) and by the large one
    (LAPACK's left and right vectors, ψᵢᵀ·φᵢ ~ 10⁻¹⁶) alike; the same matrix with the
    coupling block zero (two distinct copies of the pair: diagonalisable) is not."""
    r = np.array([[0.0, 1.0], [-1.0, 0.0]])
    jordan = np.block([[r, np.eye(2)], [np.zeros((2, 2)), r]])
    plain = np.block([[r, np.zeros((2, 2))], [np.zeros((2, 2)), r]])
    for states in (modal.LEFT_VECTORS_STATES, 1):
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(modal, "LEFT_VECTORS_STATES", states)
            with pytest.raises(modal.ModalError, match="defective"):
                modal.state_modes(jordan)
            np.testing.assert_allclose(modal.state_modes(plain).roots, [1j, 1j], atol=1e-12)


def test_a_pair_within_rounding_of_the_real_axis_keeps_both_roots_on_both_paths() -> None:
    """Roots −1 ± 10⁻¹³·i lie within the Im λ ≥ 0 tolerance: both are listed, the second
    with the conjugate vector — LAPACK stores the pair's vector once, as its real and
    imaginary parts in the first root's two columns — on the large path as on the small
    one; beside them an oscillator (λ = −0.05 ± 1.9994i) and a real root (−2)."""
    import scipy.linalg

    b = 1e-13
    a = scipy.linalg.block_diag([[-1.0, b], [-b, -1.0]], [[0.0, 1.0], [-4.0, -0.1]], [[-2.0]])
    a[0, 2] = a[1, 4] = 0.3  # one-way couplings: the same roots, vectors over several states
    small = modal.state_modes(a)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(modal, "LEFT_VECTORS_STATES", 1)
        large = modal.state_modes(a)
    assert len(large.roots) == len(small.roots) == 4
    _same_modes(large, small)


def test_state_modes_keep_the_real_roots_of_an_overdamped_mode():
    """A mutation survivor (`modal`, state_modes' tolerance sign): a root with Im λ = 0 — an
    overdamped mode's, ẍ + 3ẋ + x = 0, λ = (−3 ± √5)/2 — is listed (the .lin reader names
    the roots it leaves out from this list), each with participation summing to 1."""
    import math

    a = np.array([[0.0, 1.0], [-1.0, -3.0]])
    found = modal.state_modes(a)
    expected = sorted([(-3 - math.sqrt(5)) / 2, (-3 + math.sqrt(5)) / 2])
    np.testing.assert_allclose(sorted(found.roots.real), expected, rtol=1e-12)
    np.testing.assert_allclose(found.participation.sum(axis=0), 1.0, rtol=1e-12)


def test_a_modes_eigenvalue_is_the_inverse_of_its_frequency_and_damping():
    """λ = ω₀(−ζ + i√(1 − ζ²)): |λ| = ω₀ and −Re λ/|λ| = ζ (what DampedModes reports of a
    root), the upper root of a single oscillator m·q̈ + c·q̇ + k·q = 0 (by hand: k = 400,
    m = 1, c = 2 → ω₀ = 20, ζ = 0.05); a root past critical is real."""
    import numpy as np

    from wtvib.numerics import modal

    lam = modal.eigenvalue(20 / (2 * np.pi), 0.05)
    roots = np.roots([1.0, 2.0, 400.0])
    assert complex(lam) == pytest.approx(complex(roots[np.argmax(roots.imag)]), rel=1e-12)
    lams = modal.eigenvalue(np.array([0.3, 1.2]), np.array([0.01, 0.2]))
    assert np.abs(lams) / (2 * np.pi) == pytest.approx([0.3, 1.2])
    assert -lams.real / np.abs(lams) == pytest.approx([0.01, 0.2])
    assert complex(modal.eigenvalue(1.0, 1.5)) == pytest.approx(-1.5 * 2 * np.pi)


def test_the_lags_own_whirling_roots_are_told_from_the_structures():
    """One oscillator (ω₀ = 10 rad/s) coupled both ways to a pair of lag states whirling at
    −1 ± 3i (a cyclic filter's poles, the multi-blade lift lag): of the four roots of the
    state matrix, the structure owns the pair near 10 rad/s by participation factors and the
    filter the pair near 3 rad/s — only the structure's is an oscillation of the turbine."""
    import numpy as np

    from wtvib.numerics import modal

    k, m, d = np.array([[100.0]]), np.array([[1.0]]), np.array([[0.2]])
    rates = np.array([[-1.0, 3.0], [-3.0, -1.0]])
    lag = (np.array([[3.0, 1.0]]), np.array([[2.0], [0.0]]), np.array([[1.0], [0.5]]), rates)
    every = np.linalg.eigvals(modal.state_matrix(k, m, d, lag))
    assert sorted(np.abs(every.imag)) == pytest.approx([2.93, 2.93, 10.19, 10.19], abs=0.01)
    ((lam, _),) = modal.oscillations_stacked(k[None], m, d[None], lag=tuple(a[None] for a in lag))
    assert len(lam) == 1 and abs(lam[0].imag) == pytest.approx(10.19, abs=0.01)
    # strongly coupled to a filter whirling at 11.3 rad/s, the two pairs share their states
    # 56 : 44 by participation — still one the structure's (near 10.0 rad/s), one the lag's
    rates = np.array([[-1.9, 11.3], [-11.3, -1.9]])
    lag = (
        np.array([[-3.1, 0.2]]),
        np.array([[-11.6], [-1.1]]),
        np.array([[-1.25], [-0.73]]),
        rates,
    )
    ((lam, _),) = modal.oscillations_stacked(k[None], m, d[None], lag=tuple(a[None] for a in lag))
    assert len(lam) == 1 and lam[0].imag == pytest.approx(10.024, abs=1e-3)


def test_the_greedy_assignment_serves_the_most_certain_row_first():
    """Greedy (more rows than the exhaustive search takes, or candidates to spare): the row
    with the highest similarity picks first. Rows 0 and 1 both resemble column 0, row 0 more
    (0.9 against 0.85): it takes column 0 and row 1 the next free column it resembles most —
    by hand; serving row 1 first would give it column 0 and row 0 column 1."""
    import numpy as np

    from wtvib.numerics import modal

    score = np.zeros((8, 9))
    score[0, :2] = [0.9, 0.8]
    score[1, :2] = [0.85, 0.1]
    for i in range(2, 8):
        score[i, i] = 0.95  # the others unambiguous (and above both)
    order = modal.assign(score)
    assert list(order[:2]) == [0, 1] and list(order[2:]) == list(range(2, 8))


def _stiff_chain(
    n: int, stiffness: float = 1e6, free: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """A spring–mass chain of ``n`` unit masses, fixed at one end (free at both: a rigid
    mode at 0 Hz)."""
    k = np.zeros((n, n))
    for i in range(n - 1):
        k[i : i + 2, i : i + 2] += stiffness * np.array([[1.0, -1.0], [-1.0, 1.0]])
    if not free:
        k[0, 0] += stiffness
    return k, np.diag(np.linspace(1.0, 2.0, n))


def test_a_large_free_chain_keeps_its_rigid_mode_and_a_buckling_one_is_refused():
    """A free chain's rigid mode (0 Hz to rounding) passes; a negative stiffness — an
    eigenvalue below −σ, K + σM without a Cholesky factor — is refused as unstable; a mass
    matrix that is not positive definite is refused as that."""
    n = 705  # a large model, as a tower of 200 elements makes
    k, m = _stiff_chain(n, free=True)
    found = modal.solve(k, m, 4)
    assert found.frequency_hz[0] < 1e-3 * found.frequency_hz[1]
    k[0, 0] -= 5e4  # a spring to the ground of negative stiffness
    with pytest.raises(modal.ModalError, match="unstable"):
        modal.solve(k, m, 4)
    k, m = _stiff_chain(n)
    m[3, 3] = -1.0
    with pytest.raises(modal.ModalError, match="positive definite"):
        modal.solve(k, m, 4)


@pytest.fixture
def threads():
    """modal.set_threads for one test, one thread again after it."""
    yield modal.set_threads
    modal.set_threads(1)


def test_a_stack_shared_out_over_threads_is_solved_to_the_same_bits(threads, monkeypatch):
    """A sweep's stack of damped problems with lag states (60 coordinates, 3 lag states,
    13 points) and of undamped ones, shared out over three threads: each problem is solved
    alone as in one call, so the roots, shapes and frequencies are the same bits — and the
    eigen-solver did get the stack in parts (13 problems: 4, 4 and 5)."""
    rng = np.random.default_rng(7)
    n, p = 60, 13
    k, m = _stiff_chain(n)
    ks = k[None] * rng.uniform(0.8, 1.2, (p, 1, 1))
    ds = 1e-3 * ks + 0.1 * np.eye(n)
    lag = (
        rng.standard_normal((p, n, 3)),
        rng.standard_normal((p, 3, n)),
        0.1 * rng.standard_normal((p, 3, n)),
        np.broadcast_to(np.diag([-1.0, -2.0, -3.0]), (p, 3, 3)),
    )

    def both() -> tuple[list, list]:
        return modal.oscillations_stacked(ks, m, ds, lag=lag), modal.solve_stacked(
            ks, np.broadcast_to(m, ks.shape)
        )

    damped_one, undamped_one = both()
    assert all(len(lam) > 10 for lam, _ in damped_one)
    threads(3)
    sizes: list[int] = []
    eig = np.linalg.eig
    monkeypatch.setattr(np.linalg, "eig", lambda a: sizes.append(len(a)) or eig(a))
    damped_three, undamped_three = both()
    assert sorted(sizes) == [4, 4, 5]
    found = modal._each(np.linalg.eig, np.broadcast_to(k, (13, n, n)))  # as one call's
    assert type(found) is type(np.linalg.eig(k[None])) and found.eigenvalues.shape == (13, n)
    for (lam1, vec1), (lam3, vec3) in zip(damped_one, damped_three, strict=True):
        assert np.array_equal(lam1, lam3) and np.array_equal(vec1, vec3)
    for one, three in zip(undamped_one, undamped_three, strict=True):
        assert np.array_equal(one.frequency_hz, three.frequency_hz)
        assert np.array_equal(one.shapes, three.shapes)


def test_a_repeated_eigenvalues_shapes_are_one_basis_whatever_the_rounding():
    """An eigenvalue that repeats (a symmetric floater's surge and sway, a round beam's
    flap and edge) has a space of shapes, and LAPACK returns whichever basis of it its
    rounding leads to. solve gives the one basis the space has: any other basis of it —
    turned by a random rotation — comes back the same; the shapes M-orthonormal and each
    an eigenvector; a space of coordinates (a diagonal problem) comes back as its
    coordinates, in their order."""
    rng = np.random.default_rng(7)
    q, _ = np.linalg.qr(rng.standard_normal((6, 6)))  # a frame that mixes every coordinate
    k = q @ np.diag([2.0, 2.0, 2.0, 5.0, 7.0, 9.0]) @ q.T
    m = np.diag(np.linspace(1.0, 2.0, 6))
    k = np.sqrt(m) @ k @ np.sqrt(m)  # K φ = 2 M φ on a three-dimensional space
    found = modal.solve(k, m, 4)
    turn, _ = np.linalg.qr(rng.standard_normal((3, 3)))
    shared = np.array([True, True, False])
    again = modal._one_basis(found.shapes[:, :3] @ turn, m, shared[:2])
    np.testing.assert_allclose(again, found.shapes[:, :3], atol=1e-12)
    np.testing.assert_allclose(found.shapes.T @ m @ found.shapes, np.eye(4), atol=1e-12)
    np.testing.assert_allclose(k @ found.shapes[:, :3], 2.0 * m @ found.shapes[:, :3], atol=1e-9)
    flat = modal.solve(np.diag([2.0, 4.0, 6.0]), np.diag([1.0, 2.0, 3.0]), 3)
    assert list(np.argmax(np.abs(flat.shapes), axis=0)) == [0, 1, 2]
    assert np.allclose(np.abs(flat.shapes), np.diag(1 / np.sqrt([1.0, 2.0, 3.0])), atol=1e-12)


def test_a_free_chain_with_a_far_stiffer_link_keeps_its_soft_mode():
    """Three free masses, the first two joined by a spring 10¹⁴ times stiffer than the one
    to the third (a rigid shaft typed as a stiff one, on a free rotor): the soft mode is the
    two-mass closed form, ω² = k(M₁₂ + m₃)/(M₁₂·m₃) with M₁₂ = m₁ + m₂, to within
    k/k_stiff. K is singular (the chain is free: σ shifts it), and a reduction with M's
    factor rounds ω² to ε·10¹⁴ — the soft mode 1 % off."""
    m1, m2, m3, stiff, soft = 1.0, 2.0, 3.0, 1e14, 1.0
    k = np.array([[stiff, -stiff, 0.0], [-stiff, stiff + soft, -soft], [0.0, -soft, soft]])
    found = modal.solve(k, np.diag([m1, m2, m3]), 2)
    expected = math.sqrt(soft * (m1 + m2 + m3) / ((m1 + m2) * m3)) / (2 * math.pi)
    assert found.frequency_hz[1] == pytest.approx(expected, rel=1e-9)
    assert found.frequency_hz[0] < 1e-6
