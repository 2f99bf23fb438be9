# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Measured topic rates from a recording (ROS 1 ``.bag``, ROS 2 bags).

Read with the ``rosbags`` library (pure Python: no ROS installation), as
a stream: only a count and the first and last timestamps are kept per
topic, so memory grows with the topics, not the messages. A topic's rate
is ``(messages - 1) / (last - first)``: the time between its own first
and last message, so the seconds a recorder ran before the topic started
(or after it stopped) do not dilute it.
"""

from dataclasses import dataclass
from pathlib import Path
import time
from typing import Optional

# a progress line when reading takes longer than this
PROGRESS_SECONDS = 2.0


class BagError(Exception):
    """A recording that cannot be read (one sentence)."""


@dataclass
class TopicRecording:
    """What a bag holds of one topic."""

    topic: str
    msg_type: str
    count: int = 0
    first_ns: Optional[int] = None
    last_ns: Optional[int] = None

    @property
    def hz(self):
        """The measured rate, or None with fewer than two timestamps."""
        if self.count < 2 or self.first_ns is None or \
                self.last_ns <= self.first_ns:
            return None
        return (self.count - 1) * 1e9 / (self.last_ns - self.first_ns)


def measure_bag(path, progress=None):
    """{topic: :class:`TopicRecording`} of one bag.

    :param path: a ROS 1 ``.bag`` file or a ROS 2 bag directory (sqlite3
      or MCAP storage)
    :param progress: called with a line now and then on long bags
    :raises BagError: for a bag that is missing, truncated, of an unknown
      format, empty, or whose messages carry no usable timestamps
    """
    try:
        from rosbags.highlevel import AnyReader
    except ImportError:
        raise BagError(
            'reading bags needs the rosbags library: pip install rosbags '
            "(or colcon-rsia's [bags] extra)") from None
    path = Path(path)
    if not path.exists():
        raise BagError(f'{path}: no such bag')
    topics = {}
    started = reported = time.monotonic()
    count = 0
    try:
        with AnyReader([path]) as reader:
            for connection, timestamp, _ in reader.messages():
                recording = topics.get(connection.topic)
                if recording is None:
                    recording = topics[connection.topic] = TopicRecording(
                        connection.topic, connection.msgtype)
                recording.count += 1
                if recording.first_ns is None or \
                        timestamp < recording.first_ns:
                    recording.first_ns = timestamp
                if recording.last_ns is None or timestamp > recording.last_ns:
                    recording.last_ns = timestamp
                count += 1
                if progress is not None and count % 1000 == 0 and \
                        time.monotonic() - reported > PROGRESS_SECONDS:
                    reported = time.monotonic()
                    progress(f'{path}: {count} messages read in '
                             f'{reported - started:.0f} s')
    except BagError:
        raise
    except Exception as e:  # noqa: B902
        # rosbags raises its own error classes, and struct/OS/value errors
        # on truncated or foreign files: all say the same to a user
        raise BagError(
            f'{path}: cannot be read as a ROS 1 or ROS 2 bag '
            f'({type(e).__name__}: {e})') from None
    if not topics:
        raise BagError(f'{path}: the bag holds no message')
    if all(r.hz is None for r in topics.values() if r.count >= 2) and \
            any(r.count >= 2 for r in topics.values()):
        raise BagError(f'{path}: its messages carry no usable timestamps '
                       '(all equal); no rate can be measured')
    return topics
