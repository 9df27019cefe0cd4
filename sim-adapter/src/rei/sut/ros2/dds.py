"""One way to read a DDS topic with a callback that is safe from the reader's first sample on."""

from __future__ import annotations

from collections.abc import Callable

from cyclonedds.core import Listener, Qos
from cyclonedds.domain import DomainParticipant
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic


def listening_reader(participant: DomainParticipant, topic: Topic, qos: Qos | None,
                     on_data: Callable[[DataReader], None]) -> DataReader:
    """A reader whose ``on_data`` runs for every sample, those that arrived while it was being built included.

    cyclonedds-python calls a listener passed to ``DataReader(...)`` as soon as data arrives, before the reader
    has its topic: ``take()`` then raises in the listener's thread and the sample is never delivered again (for a
    latched map or a goal reply, lost for good). So the listener is attached after construction, and what came
    in before it is taken once here.
    """
    reader = DataReader(participant, topic, qos=qos)
    reader.set_listener(Listener(on_data_available=on_data))
    on_data(reader)
    return reader

