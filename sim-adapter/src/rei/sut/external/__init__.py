# SPDX-License-Identifier: EPL-2.0
"""External systems under test: robot software in another process, on the run's router (docs/sut.md).

``session.external_sut`` is what the mission loop uses instead of an in-process controller: it offers ``hello``,
starts the SUT command (``--sut``) or waits for one started by the user (``--sut-attach``), and at the end tells
the SUT to leave and stops what it started. The other modules: ``protocol`` (the messages and their rules),
``options`` (``SutOptions``), ``process`` (starting a SUT), ``controller`` (``ExternalController``, ``SutError``).

This package imports nothing itself, so the command line can check ``options`` without loading the WAMP client.
"""
