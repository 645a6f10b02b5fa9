# Observers on a [layer] (issue 27): mdr.run(layer_case, observers=[...]) sees every state of the run that gives the
# result, in order, with the values of its history rows, on Ting's path, on the cells and in an impact; a true return
# stops the run there and an exception propagates; a run of Ting's class is made once. The independent expectation is
# the run's own history table (output_every = 1: one row a state), written by the drivers' row recording, not by the
# observers.
from __future__ import annotations

import numpy as np
import pytest

import mdr


def layer_case(history, **changes):
    given = dict(material=mdr.Material.standard(G_inf=1e6, G1=2e6, tau1=0.3),
                 indenter=mdr.Indenter.sphere(R=0.01), control=mdr.DisplacementControl(), history=history,
                 layer=mdr.Layer(thickness=1e-3, interface="bonded"), numerics=mdr.Numerics(elements=40))
    given.update(changes)
    return mdr.ContactCase(**given)


LOADING = [(0.0, 0.0), (1.0, 5e-5), (2.0, 5e-5)]             # one maximum of the radius: Ting's class (eq. L12)
RELOADING = [(0.0, 0.0), (1.0, 5e-5), (2.0, 2e-5), (3.0, 6e-5)]  # the contact grows again: the cells (eq. L16)

CASES = {
    "ting": lambda: layer_case(LOADING),
    "cells": lambda: layer_case(RELOADING),
    "force": lambda: layer_case([(0.0, 0.0), (1.0, 0.05), (3.0, 0.05)], control=mdr.ForceControl()),
    "impact": lambda: layer_case(None, control=mdr.ImpactControl(mass=1e-3, velocity=0.05)),
}


def observed(case, **kwargs):
    steps = []
    result = mdr.run(case, observers=[steps.append], **kwargs)
    return steps, result


@pytest.mark.parametrize("name", sorted(CASES))
def test_observers_see_every_state_of_a_layer_run_as_its_rows(name):
    steps, result = observed(CASES[name]())
    history = result.history
    assert [step.step for step in steps] == list(range(len(steps)))  # each state once, in order: no restart
    assert len(steps) == len(history["t"]) == result.summary["steps"] + 1
    np.testing.assert_array_equal([step.time for step in steps], history["t"])
    np.testing.assert_array_equal([step.depth for step in steps], history["d"])
    np.testing.assert_array_equal([step.force for step in steps], history["F"])
    np.testing.assert_array_equal([step.contact_radius for step in steps], history["a"])
    assert steps[-1].fraction == 1.0  # an impact's too, at the end of its contact
    if name == "cells":  # the reload: the depth prescribed is the load, and the contact came back
        np.testing.assert_array_equal([step.load for step in steps], history["d"])
        assert max(history["a"]) > 0.0


@pytest.mark.parametrize("name", sorted(CASES))
def test_an_observer_stops_a_layer_run_with_its_state(name):
    full = mdr.run(CASES[name]()).history
    stop_time = full["t"][len(full["t"]) // 2]
    seen = []

    def until(step):
        seen.append(step.time)
        return step.time >= stop_time

    stopped = mdr.run(CASES[name](), observers=[until]).history
    assert stopped["t"][-1] == stop_time and seen[-1] == stop_time and len(seen) == len(stopped["t"])
    np.testing.assert_array_equal(stopped["F"], full["F"][:len(stopped["F"])])  # the same run, cut there


@pytest.mark.parametrize("name", sorted(CASES))
def test_an_observers_exception_abandons_a_layer_run(name):
    class Abandon(Exception):
        pass

    def fail(step):
        if step.step == 5:
            raise Abandon(step.time)

    with pytest.raises(Abandon):
        mdr.run(CASES[name](), observers=[fail])


@pytest.mark.parametrize("name", ["ting", "force"])
def test_a_layer_run_of_tings_class_with_observers_runs_once(name):
    # Its observers see its states once it has ended in Ting's class: the same progress as a run without them (before,
    # the run was made once without observers to learn its class and again with them: each report twice).
    def reports(**kwargs):
        fractions = []
        mdr.run(CASES[name](), progress=fractions.append, **kwargs)
        return fractions

    steps = []
    assert reports(observers=[steps.append]) == reports()
    assert [step.step for step in steps] == list(range(len(steps)))
