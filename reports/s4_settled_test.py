"""s4_settled.ladder_limit on ladders worked by hand: a ladder converges only when its asymptotic
range has three rungs or more whose differences shrink in size; a ladder that wanders (its last
difference as large as the one before) or has two rungs converges nowhere, and the committed
settled.json says what the rule says of its stored ladders."""
import json
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import s4_settled  # noqa: E402
from s4_settled import PENALTY_MIN_ORDER, ladder_limit  # noqa: E402


def test_a_ladder_of_first_order_converges_onto_its_richardson_limit():
    # q_k = 1 + 2^-k (k = 1..4): differences halve, order 1 in a step halved each rung, limit 1.
    # Roundoff of the sums and of log(2)/log(2): 1e-12.
    r = ladder_limit([1.5, 1.25, 1.125, 1.0625], 2.0)
    assert r["converged"] is True
    assert r["rungs_used"] == 4
    assert r["order"] == pytest.approx(1.0, abs=1e-12)
    assert r["limit"] == pytest.approx(1.0, abs=1e-12)
    assert r["uncertainty"] == pytest.approx(1.25 * 0.0625, abs=1e-12)  # 1.25 x the last correction


def test_a_ladder_that_oscillates_inside_a_shrinking_band_converges():
    # q_k = 1 + (-1/2)^k: the differences change sign and halve in size; no observed order (the
    # rungs are not monotone), the last rung with the larger of the last two differences.
    r = ladder_limit([0.5, 1.25, 0.875, 1.0625], 2.0)
    assert r["converged"] is True
    assert r["order"] is None
    assert r["limit"] == 1.0625
    assert r["uncertainty"] == pytest.approx(0.375, abs=1e-12)


def test_a_wandering_ladder_does_not_converge():
    # FEniCSx's S4-60 impulse (N s): +408, -129, -457; the last difference is larger than the one
    # before, so the asymptotic range read back from the finest rung holds two rungs only.
    r = ladder_limit([18736.5, 19144.7, 19016.0, 18558.8], 2.0)
    assert r["rungs_used"] == 2
    assert r["converged"] is False
    assert r["limit"] == 18558.8  # still reported, not claimed


def test_two_rungs_show_no_contraction():
    assert ladder_limit([1.0, 1.1], 2.0)["converged"] is False
    assert ladder_limit([7, 7, 7, 7], 2.0)["converged"] is False  # differences 0: none shrinks


def test_a_penalty_ladder_is_read_from_its_softest_rung_up():
    # Differences 0.1, 0.01, then 0.39 (the stiffest penalty unresolved): the first three rungs,
    # order 1 per decade of the penalty, above PENALTY_MIN_ORDER.
    r = ladder_limit([1.0, 1.1, 1.11, 1.5], 10.0, from_fine_end=False, min_order=PENALTY_MIN_ORDER)
    assert r["rungs_used"] == 3 and r["converged"] is True
    assert r["order"] == pytest.approx(1.0, abs=1e-9)
    # 0.1 then 0.2: the penalty ladder wanders from its second rung.
    r = ladder_limit([1.0, 1.1, 1.3, 1.35], 10.0, from_fine_end=False, min_order=PENALTY_MIN_ORDER)
    assert r["rungs_used"] == 2 and r["converged"] is False


def test_a_contracting_ladder_below_the_least_order_does_not_converge():
    # Differences shrinking by 2^0.3 a rung: observed order 0.3 < 0.5 (a step ladder's least).
    d = [1.0, 2 ** -0.3, 2 ** -0.6]
    q = [0.0, d[0], d[0] + d[1], d[0] + d[1] + d[2]]
    r = ladder_limit(q, 2.0)
    assert r["order"] == pytest.approx(0.3, abs=1e-12)
    assert r["converged"] is False


def test_the_committed_settled_json_follows_the_rule():
    with open(os.path.join(ROOT, "reports", "s4", "settled.json")) as f:
        doc = json.load(f)
    for angle, a in doc["angles"].items():
        for q, entry in a["quantities"].items():
            for ref, r in entry["references"].items():
                again = (ladder_limit(r["ladder"], 10.0, from_fine_end=False, min_order=PENALTY_MIN_ORDER)
                         if ref == "ida" else ladder_limit(r["ladder"], 2.0))
                assert r["converged"] == again["converged"], (angle, q, ref)
                assert r["rungs_used"] >= 3 or not r["converged"], (angle, q, ref)
            ind = [entry["references"][x]["converged"] for x in ("siconos", "ida")]
            assert entry["gated"] == (s4_settled.QUANTITIES[q][1] and all(ind)), (angle, q)
            assert ("value" in entry) == entry["gated"], (angle, q)
