# SPDX-License-Identifier: EPL-2.0
"""Search-based scenario generation (`rei search`, docs/search.md): find the situations that make the robot fail.

``load_search_spec(path)`` -> ``run_search(spec, out, workers=N | ray=ADDRESS)``. Modules, in the order of
imports: ``spec`` (the YAML, placed errors), ``base`` (a ``rooms:`` spec's generated base case), ``space`` (parameters as Optuna distributions and as the room
editor's operations), ``reproduce`` (the `rei run` line of a saved case), ``candidates`` (the base case edited, validated, checked for a path, generated),
``objectives``, ``failures``, ``pool`` (the campaign's supervised workers, one run at a time), ``study`` (Optuna's
ask/tell loop over a journal), ``shrink``, ``outputs`` and ``report``, and ``run``, which ties them together.
This package may import rei.campaign, rei.evaluation, rei.edit, rei.rooms and rei.report; only rei.cli imports it.
"""

#: The optimizers (``sampler:`` / ``--sampler``); here, with no import, so the command line lists them cheaply.
SAMPLERS = ("tpe", "cmaes", "nsga2", "qmc", "random")
