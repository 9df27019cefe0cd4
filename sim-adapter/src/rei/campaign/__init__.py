# SPDX-License-Identifier: EPL-2.0
"""Campaigns (thesis 7.4-7.5): many missions from a spec, in parallel, summarized like the thesis's tables.

``load_spec(path)`` -> ``run_campaign(spec, out, LocalBackend(workers) | RayBackend(address))``; one process per
run (``rei.campaign.worker``), supervised with a timeout (``rei.campaign.supervise``). Spec format, outputs and
the per-run path: docs/campaigns.md.
"""

from rei.campaign.backends import LocalBackend, RayBackend
from rei.campaign.plan import Plan, RunTask, plan_campaign
from rei.campaign.results import RunResult
from rei.campaign.runner import CampaignResult, run_campaign
from rei.campaign.spec import Spec, SpecError, load_spec, parse_spec

__all__ = [
    "CampaignResult",
    "LocalBackend",
    "Plan",
    "RayBackend",
    "RunResult",
    "RunTask",
    "Spec",
    "SpecError",
    "load_spec",
    "parse_spec",
    "plan_campaign",
    "run_campaign",
]
