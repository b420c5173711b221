"""The contact-interval rule of the suite for the Python references (FEniCSx, Siconos, GetFEM):
the same rule as solver/record/ContactIntervals.hpp, which every C++ method and `compare` use.
A contact phase that begins less than the merge gap after the last interval's end joins that
interval (chatter); otherwise it opens a new one. The default gap merges fewer than MERGE_STEPS
open samples: (MERGE_STEPS + 0.5) steps (two phases n open samples apart are n + 1 steps apart;
the half step keeps round-off in the times from deciding the count).

python/tests/test_contact_stats_conformance.py checks this module, and every reference's
statistics built on it, against the C++ rule sample for sample. Pure Python: no dolfinx, numpy or
other import, so that every reference can load it."""

MERGE_STEPS = 3  # as kMergeSteps (solver/record/ContactIntervals.hpp)


def merge_gap(step, open_steps=MERGE_STEPS):
    """@brief s, the merge gap of samples `step` s apart that merges fewer than `open_steps` open
    samples: (open_steps + 0.5) steps (merge_gap_of in ContactIntervals.hpp).
    @param step s, the time step or the spacing of the samples; @param open_steps a whole number >= 0"""
    return (open_steps + 0.5) * step


def merge_rule(step, open_steps=MERGE_STEPS):
    """@brief The summary's `merge_rule` text for merge_gap(step, open_steps), as the paper's."""
    return (f"contact phases separated by fewer than {open_steps} open steps ({open_steps * step:.6g} s) are "
            "merged; an interval runs from its first to its last step with R > 0")


class ContactIntervals:
    """Contact intervals [start, end, ...] (s), built phase by phase in time order (ContactIntervals
    of solver/record/ContactIntervals.hpp). Each interval is a list whose first two items are its
    start and end; a caller may keep more items after them (a peak, the closure's force)."""

    def __init__(self, gap):
        """@param gap s, a phase beginning less than this after the last interval's end joins it."""
        self.merge_gap = gap
        self.intervals = []

    def begin(self, t, *extra):
        """@brief A phase begins at t (s). Returns True when it opens a new interval [t, t, *extra],
        False when it joins the last one (whose end becomes t)."""
        if self.intervals and t - self.intervals[-1][1] < self.merge_gap:
            self.intervals[-1][1] = t
            return False
        self.intervals.append([t, t, *extra])
        return True

    def extend(self, t):
        """@brief The current phase lasts until at least t (s): the last interval's end becomes t."""
        self.intervals[-1][1] = t
