# Copyright 2026 colcon-rsia contributors
# Licensed under the Apache License, Version 2.0
"""Drive a real headless Chromium through the DevTools protocol.

The protocol runs over ``--remote-debugging-pipe`` (JSON messages ended by
NUL on file descriptors 3 and 4), so no port and no websocket client are
needed. Console messages, exceptions, log entries and network requests of
the page are recorded while it loads.
"""

import base64
import fcntl
import json
import os
from pathlib import Path
import select
import shutil
import subprocess
import sys
import time

CHROMIUM_NAMES = ('chromium', 'chromium-browser', 'google-chrome')


def find_chromium():
    """The Chromium executable on PATH (or /usr/bin/chromium), or None."""
    for name in CHROMIUM_NAMES:
        found = shutil.which(name)
        if found:
            return found
    return '/usr/bin/chromium' if os.path.exists('/usr/bin/chromium') \
        else None


def chromium_for_test():
    """Chromium, or the test skipped (failed in CI, which installs it)."""
    import pytest  # (the benchmarks use this module without pytest)
    executable = find_chromium()
    if executable is None:
        if os.environ.get('CI'):
            pytest.fail('chromium is not installed (.ci/install installs it)')
        pytest.skip('chromium is not installed')
    return executable


def artifacts_directory(tmp_path):
    """Where a test keeps its screenshots: RSIA_TEST_ARTIFACTS or tmp."""
    directory = os.environ.get('RSIA_TEST_ARTIFACTS')
    if not directory:
        return tmp_path
    Path(directory).mkdir(parents=True, exist_ok=True)
    return Path(directory)


# run argv[3:] with the fds argv[1] and argv[2] as fds 3 and 4
ON_FDS_3_AND_4 = (
    'import os, sys; '
    'os.dup2(int(sys.argv[1]), 3); os.dup2(int(sys.argv[2]), 4); '
    'os.execvp(sys.argv[3], sys.argv[3:])')


def _high(fd):
    """The fd moved to a number of at least 10 (close-on-exec)."""
    moved = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return moved


class BrowserError(RuntimeError):
    pass


class Browser:
    """One headless Chromium with one page, as a context manager."""

    def __init__(self, executable, profile, *, width=1400, height=1000,
                 timeout=60):
        self.timeout = timeout
        self.events = []
        self._next_id = 0
        self._buffer = b''
        to_chrome_read, self._to_chrome = os.pipe()
        self._from_chrome, from_chrome_write = os.pipe()
        # above 4, so that moving one to 3 or 4 cannot clobber the other
        to_chrome_read = _high(to_chrome_read)
        from_chrome_write = _high(from_chrome_write)
        args = [
            executable, '--headless', '--no-sandbox', '--disable-gpu',
            '--disable-background-networking', '--disable-component-update',
            '--disable-sync', '--disable-default-apps', '--no-first-run',
            '--disable-extensions', '--mute-audio',
            f'--user-data-dir={profile}', f'--window-size={width},{height}',
            '--remote-debugging-pipe', 'about:blank']
        # the pipe must be on fds 3 (commands) and 4 (replies)
        self.process = subprocess.Popen(
            [sys.executable, '-c', ON_FDS_3_AND_4, str(to_chrome_read),
             str(from_chrome_write)] + args,
            pass_fds=(to_chrome_read, from_chrome_write),
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE)
        os.close(to_chrome_read)
        os.close(from_chrome_write)
        self.session = None

    def __enter__(self):  # noqa: D105
        target = self.send('Target.createTarget', {'url': 'about:blank'},
                           session=False)['targetId']
        self.session = self.send(
            'Target.attachToTarget', {'targetId': target, 'flatten': True},
            session=False)['sessionId']
        for domain in ('Page', 'Runtime', 'Log', 'Network'):
            self.send(f'{domain}.enable')
        return self

    def __exit__(self, *exc):  # noqa: D105
        try:
            self.send('Browser.close', session=False)
        except (BrowserError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.stderr = self.process.stderr.read().decode('utf-8', 'replace')
        self.process.stderr.close()
        os.close(self._to_chrome)
        os.close(self._from_chrome)

    # --- the protocol ------------------------------------------------------

    def send(self, method, params=None, *, session=True):
        """Call a method; return its result (events meanwhile recorded)."""
        self._next_id += 1
        message = {'id': self._next_id, 'method': method,
                   'params': params or {}}
        if session and self.session:
            message['sessionId'] = self.session
        os.write(self._to_chrome, json.dumps(message).encode() + b'\0')
        while True:
            reply = self._read()
            if reply.get('id') == self._next_id:
                if 'error' in reply:
                    raise BrowserError(f'{method}: {reply["error"]}')
                return reply.get('result', {})

    def wait_for(self, method, since=0):
        """Wait for an event (or find it among those recorded from `since`)."""
        for event in self.events[since:]:
            if event['method'] == method:
                return event
        while True:
            message = self._read()
            if message.get('method') == method:
                return message

    def _read(self):
        deadline = time.monotonic() + self.timeout
        while b'\0' not in self._buffer:
            left = deadline - time.monotonic()
            ready, _, _ = select.select([self._from_chrome], [], [],
                                        max(0, left))
            if not ready:
                raise BrowserError(
                    f'no answer from Chromium within {self.timeout} s')
            chunk = os.read(self._from_chrome, 1 << 20)
            if not chunk:
                raise BrowserError(
                    'Chromium closed the DevTools pipe:\n' + self._tail())
            self._buffer += chunk
        raw, self._buffer = self._buffer.split(b'\0', 1)
        message = json.loads(raw)
        if 'method' in message:
            self.events.append(message)
        return message

    def _tail(self):
        """The end of Chromium's stderr, once it has exited."""
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            return '(Chromium is still running)'
        return self.process.stderr.read().decode('utf-8', 'replace')[-3000:]

    # --- conveniences ------------------------------------------------------

    def open(self, url):
        """Navigate and wait for the load event."""
        since = len(self.events)
        result = self.send('Page.navigate', {'url': url})
        if result.get('errorText'):
            raise BrowserError(f'cannot open {url}: {result["errorText"]}')
        self.wait_for('Page.loadEventFired', since)

    def evaluate(self, expression):
        """The value of a JavaScript expression (promises awaited)."""
        result = self.send('Runtime.evaluate', {
            'expression': expression, 'returnByValue': True,
            'awaitPromise': True})
        if 'exceptionDetails' in result:
            raise BrowserError(
                f'{expression}: {result["exceptionDetails"]}')
        return result['result'].get('value')

    def screenshot(self, path):
        """Write a PNG of the viewport."""
        data = self.send('Page.captureScreenshot', {'format': 'png'})['data']
        with open(path, 'wb') as h:
            h.write(base64.b64decode(data))

    def problems(self):
        """Console errors and warnings, exceptions and error log entries."""
        found = []
        for event in self.events:
            method, params = event['method'], event.get('params', {})
            if method == 'Runtime.exceptionThrown':
                found.append(f'exception: {params["exceptionDetails"]}')
            elif method == 'Runtime.consoleAPICalled' and \
                    params.get('type') in ('error', 'warning', 'assert'):
                found.append(f'console.{params["type"]}: {params["args"]}')
            elif method == 'Log.entryAdded' and \
                    params['entry'].get('level') in ('error', 'warning'):
                found.append(f'log: {params["entry"]}')
        return found

    def requests(self):
        """The URLs the page requested."""
        return [e['params']['request']['url'] for e in self.events
                if e['method'] == 'Network.requestWillBeSent']
