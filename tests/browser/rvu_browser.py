#!/usr/bin/env python3
"""Browser test of rvu's web display: starts an rvu-like server, drives headless
Chromium through chromedriver (W3C WebDriver over plain HTTP) and checks the page.

    rvu_browser.py --screenshot OUT.png -- CMD ARGS...
    e.g. rvu_browser.py --screenshot /tmp/shot.png -- build/tools/rvu -vf view.vf scene.rad
Run by scripts/validate (not by scripts/test: installing Chromium would cost CI time).

Exit status: 0 passed, 1 failed, 77 skipped (no Chromium or chromedriver).
"""
import argparse
import base64
import collections
import json
import os
import queue
import re
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

CHROMIUM = '/usr/bin/chromium'
# Without the background-networking flags Chromium keeps trying to reach Google.
CHROME_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
               '--disable-background-networking', '--disable-component-update', '--disable-sync',
               '--window-size=1000,800']
ELEMENT = 'element-6066-11e4-a52e-4f735466cecf'  # W3C's key for element references
ENTER, ESCAPE, ARROW_UP = '\ue007', '\ue00c', '\ue013'
URL_LINE = re.compile(r'rvu: open (http://127\.0\.0\.1:(\d+)/\?t=(\S+)) in a web browser')
# Loopback only: a proxy from the environment must not see these requests.
OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


class Fail(Exception):
    pass


def ok(what):
    print(f'ok   {what}', flush=True)


def free_port():
    with socket.socket() as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


def http(method, url, body=None, headers=None, timeout=30):
    """(status, body bytes, headers); HTTP errors are answers too."""
    req = urllib.request.Request(url, data=body, method=method, headers=headers or {})
    try:
        with OPENER.open(req, timeout=timeout) as r:
            return r.status, r.read(), r.headers
    except urllib.error.HTTPError as e:
        return e.code, e.read(), e.headers


class Server:
    """The rvu-like process; its output is drained into a tail for failure reports."""

    def __init__(self, cmd):
        try:
            self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                         stderr=subprocess.PIPE, start_new_session=True)
        except OSError as e:
            raise Fail(f'cannot start {cmd[0]}: {e}') from None
        self.tail = collections.deque(maxlen=40)
        self.lines = queue.Queue()
        for stream in (self.proc.stdout, self.proc.stderr):
            threading.Thread(target=self.drain, args=(stream,), daemon=True).start()

    def drain(self, stream):
        for raw in iter(stream.readline, b''):
            line = raw.decode('utf-8', 'replace').rstrip('\n')
            self.tail.append(line)
            self.lines.put(line)
        self.lines.put(None)

    def wait_url(self, timeout):
        deadline = time.monotonic() + timeout
        ends = 0
        while ends < 2:
            try:
                line = self.lines.get(timeout=max(0.0, deadline - time.monotonic()))
            except queue.Empty:
                raise Fail(f'no "rvu: open http://..." line within {timeout} s') from None
            if line is None:
                ends += 1
            elif m := URL_LINE.search(line):
                return m.group(1), int(m.group(2)), m.group(3)
        raise Fail(f'server exited ({self.proc.wait()}) without printing its address')

    def stop(self):
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGTERM)
                self.proc.wait(5)
            except (ProcessLookupError, subprocess.TimeoutExpired):
                try:
                    os.killpg(self.proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                self.proc.wait()
        if self.proc.stdin:
            self.proc.stdin.close()


class WebDriver:
    def __init__(self, driver, logfile):
        self.port = free_port()
        self.proc = subprocess.Popen([driver, f'--port={self.port}'], stdin=subprocess.DEVNULL,
                                     stdout=logfile, stderr=subprocess.STDOUT,
                                     start_new_session=True)
        self.base = f'http://127.0.0.1:{self.port}'
        self.sid = None
        deadline = time.monotonic() + 20
        while True:
            try:
                if self.call('GET', '/status', timeout=2).get('ready'):
                    break
            except (Fail, OSError):
                pass
            if time.monotonic() > deadline or self.proc.poll() is not None:
                raise Fail('chromedriver did not become ready')
            time.sleep(0.1)

    def call(self, method, path, body=None, timeout=30):
        data = None if body is None else json.dumps(body).encode()
        status, reply, _ = http(method, self.base + path, data,
                                {'Content-Type': 'application/json; charset=utf-8'}, timeout)
        try:
            value = json.loads(reply or b'{}').get('value')
        except ValueError:
            value = None
        if status != 200:
            msg = value if not isinstance(value, dict) else \
                f"{value.get('error')}: {str(value.get('message', ''))[:400]}"
            raise Fail(f'WebDriver {method} {path}: HTTP {status}: {msg}')
        return value

    def start(self, profile):
        caps = {'browserName': 'chrome', 'goog:loggingPrefs': {'browser': 'ALL'},
                'goog:chromeOptions': {'binary': CHROMIUM,
                                       'args': CHROME_ARGS + [f'--user-data-dir={profile}']}}
        self.sid = self.call('POST', '/session', {'capabilities': {'alwaysMatch': caps}},
                             timeout=60)['sessionId']

    def s(self, method, path, body=None, timeout=30):
        return self.call(method, f'/session/{self.sid}{path}', body, timeout)

    def js(self, script, *args):
        return self.s('POST', '/execute/sync', {'script': script, 'args': list(args)})

    def element(self, css):
        return self.s('POST', '/element', {'using': 'css selector', 'value': css})[ELEMENT]

    def keys(self, css, text):
        self.s('POST', f'/element/{self.element(css)}/value', {'text': text})

    def actions(self, *sources):
        self.s('POST', '/actions', {'actions': list(sources)})
        self.s('DELETE', '/actions')

    def stop(self):
        if self.sid:
            try:
                self.call('DELETE', f'/session/{self.sid}', timeout=15)
            except (Fail, OSError):
                pass
        if self.proc.poll() is None:
            # The group also holds Chromium, should the session not have closed it.
            for sig in (signal.SIGTERM, signal.SIGKILL):
                try:
                    os.killpg(self.proc.pid, sig)
                    self.proc.wait(5)
                    break
                except ProcessLookupError:
                    break
                except subprocess.TimeoutExpired:
                    continue


SNAPSHOT = """
const b = document.body, img = document.getElementById('picture');
const r = img.getBoundingClientRect();
const text = (id) => document.getElementById(id).textContent;
return {generation: +b.dataset.generation, done: b.dataset.done, exposure: b.dataset.exposure,
        ended: b.dataset.ended, pick: b.dataset.pick, commands: +b.dataset.commands,
        status: text('status-text'), view: text('view'),
        prompt: document.getElementById('prompt').hidden ? '' : text('prompt'),
        input: document.getElementById('command').value,
        log: [...document.querySelectorAll('#log > *')].map((e) => e.textContent),
        errors: [...document.querySelectorAll('#log .error')].map((e) => e.textContent),
        img: {hidden: img.hidden, nw: img.naturalWidth, nh: img.naturalHeight,
              left: r.left, top: r.top, width: r.width, height: r.height,
              winW: innerWidth, winH: innerHeight}};
"""


class Test:
    def __init__(self, server, wd, url, port, token):
        self.server, self.wd, self.url, self.port, self.token = server, wd, url, port, token

    def page(self):
        return self.wd.js(SNAPSHOT)

    def wait(self, what, cond, timeout=60, server_may_exit=False):
        """Polls the page until cond(snapshot) is true; returns that snapshot."""
        deadline = time.monotonic() + timeout
        while True:
            snap = self.page()
            if cond(snap):
                return snap
            if not server_may_exit and self.server.proc.poll() is not None:
                raise Fail(f'server exited ({self.server.proc.returncode}) '
                           f'while waiting for {what}')
            if time.monotonic() > deadline:
                raise Fail(f'timed out after {timeout} s waiting for {what}; page: '
                           f'status={snap["status"]!r} done={snap["done"]} '
                           f'ended={snap["ended"]} log={snap["log"][-5:]}')
            time.sleep(0.1)

    def state(self):
        status, body, _ = http('GET', f'http://127.0.0.1:{self.port}/state',
                               headers={'X-Rvu-Token': self.token}, timeout=15)
        if status != 200:
            raise Fail(f'GET /state: HTTP {status}: {body[:200]!r}')
        return json.loads(body)

    def command(self, line, timeout=60):
        """Types line into the page's command line; returns the snapshots before and after
        the page has handled the answer."""
        before = self.page()
        self.wd.keys('#command', line + ENTER)
        after = self.wait(f'the answer to {line!r}',
                          lambda s: s['commands'] > before['commands'], timeout)
        if f': {line}' not in after['log']:
            raise Fail(f'{line!r} not echoed in the log: {after["log"][-5:]}')
        return before, after

    def gesture(self, name, expect, sources, timeout=60):
        """Plays WebDriver input sources on the picture; checks that the page sent a command
        starting with `expect`, that it was not refused and that the view changed."""
        before = self.page()
        self.wd.actions(*sources)
        after = self.wait(f'the answer to the {name}',
                          lambda s: s['commands'] > before['commands'], timeout)
        sent = [l for l in after['log'][len(before['log']):] if l.startswith(': ')]
        if not sent or not sent[0].startswith(f': {expect}'):
            raise Fail(f'{name}: expected ": {expect}..." in the log, got {sent}')
        if len(after['errors']) > len(before['errors']):
            raise Fail(f'{name}: {sent[0]!r} answered {after["errors"][-1]!r}')
        self.wait(f'the view to change after {sent[0]!r}',
                  lambda s: s['view'] != before['view'], 30)
        ok(f'{name} sends "{sent[0][2:]}" with the cursor and the view changes')

    def run(self, screenshot):
        self.check_refusals()
        self.wd.s('POST', '/url', {'url': self.url}, timeout=60)
        title = self.wd.s('GET', '/title')
        if title != 'rvu':
            raise Fail(f'page title {title!r}, expected "rvu"')
        ok('page loads, title "rvu"')

        snap = self.wait('the first refinement to finish (data-done="1")',
                         lambda s: s['done'] == '1')
        st = self.state()
        im = snap['img']
        if im['hidden'] or (im['nw'], im['nh']) != (st['width'], st['height']):
            raise Fail(f'picture hidden={im["hidden"]} natural size {im["nw"]}x{im["nh"]}, '
                       f'state says {st["width"]}x{st["height"]}')
        inside = (im['left'] >= -1 and im['top'] >= -1 and
                  im['left'] + im['width'] <= im['winW'] + 1 and
                  im['top'] + im['height'] <= im['winH'] + 1)
        if im['width'] < 50 or not inside:
            raise Fail(f'picture not shown inside the window: {im}')
        aspect = (im['width'] / im['height']) / (st['width'] / st['height'])
        if abs(aspect - 1) > 0.02:
            raise Fail(f'picture shown with the wrong aspect: {im}')
        ok(f'refinement done, picture {im["nw"]}x{im["nh"]} shown at '
           f'{im["width"]:.0f}x{im["height"]:.0f}, generation {snap["generation"]}')

        e0 = float(snap['exposure'])
        self.command('exposure +1')
        snap = self.wait('the exposure to change and the picture to be done again',
                         lambda s: float(s['exposure']) != e0 and s['done'] == '1')
        # rvu's f-stops are relative to the exposure that makes the picture's average 0.5
        # (RADIANCE's getexposure), not to the current one: only the direction is certain.
        e1 = float(snap['exposure'])
        if not e1 > e0:
            raise Fail(f'"exposure +1" took the exposure from {e0} down to {e1}')
        ok(f'"exposure +1": exposure {e0:g} -> {e1:g}, picture generation {snap["generation"]}')

        before, after = self.command('aim zz')
        if after['pick'] == '1':
            self.wd.keys('#command', ESCAPE)
            self.wait('Escape to cancel the pick',
                      lambda s: s['pick'] == '0' and not s['prompt'], 10)
            ok(f'"aim zz" asked for a pick ({after["prompt"]!r}); Escape cancelled it')
        elif len(after['errors']) > len(before['errors']):
            ok(f'"aim zz" refused: {after["errors"][-1]!r}')
        else:
            raise Fail(f'"aim zz" neither refused nor asked for a pick: {after["log"][-3:]}')

        before, after = self.command('nosuchcommand')
        new = after['errors'][len(before['errors']):]
        if not any('unknown command' in e for e in new):
            raise Fail(f'"nosuchcommand": no "unknown command" error in the log; new errors {new}')
        ok(f'"nosuchcommand" refused: {new[-1]!r}')

        st = self.state()
        self.command('exposure -1')
        snap = self.wait('the exposure to go down', lambda s: s['done'] == '1' and
                         float(s['exposure']) < e1, 30)
        if snap['generation'] <= st['generation']:
            raise Fail(f'picture generation {snap["generation"]} not newer than {st["generation"]}')
        ok(f'server still answers after the errors: "exposure -1": exposure '
           f'{float(snap["exposure"]):g}, generation {snap["generation"]}')

        self.wd.keys('#command', ARROW_UP + ARROW_UP)
        snap = self.page()
        if snap['input'] != 'nosuchcommand':
            raise Fail(f'Up Up in the command line gave {snap["input"]!r}, '
                       'expected "nosuchcommand"')
        self.wd.s('POST', f'/element/{self.wd.element("#command")}/clear', {})
        ok('command history: Up Up recalls "nosuchcommand"')

        png = base64.b64decode(self.wd.s('GET', '/screenshot'))
        if not png.startswith(b'\x89PNG'):
            raise Fail('screenshot is not a PNG')
        os.makedirs(os.path.dirname(os.path.abspath(screenshot)), exist_ok=True)
        with open(screenshot, 'wb') as f:
            f.write(png)
        ok(f'screenshot {screenshot} ({len(png)} bytes)')

        self.check_mouse()

        errors = [e for e in self.wd.s('POST', '/se/log', {'type': 'browser'})
                  if e.get('level') == 'SEVERE' and e.get('source') == 'javascript']
        if errors:
            raise Fail(f'JavaScript errors in the console: {[e["message"] for e in errors]}')
        ok('no JavaScript errors in the console')

        self.wd.keys('#command', 'quit' + ENTER)
        try:
            rc = self.server.proc.wait(10)
        except subprocess.TimeoutExpired:
            raise Fail('server still running 10 s after "quit"') from None
        if rc != 0:
            raise Fail(f'server exited with status {rc} after "quit"')
        ok('"quit": server exited with status 0')
        self.wait('the page to show that rvu has ended',
                  lambda s: s['ended'] == '1' and 'rvu has ended' in s['status'], 10, True)
        ok('page shows "rvu has ended"')

    def check_refusals(self):
        base = f'http://127.0.0.1:{self.port}'
        cases = [('no token', '/state', {}),
                 ('wrong token', '/state', {'X-Rvu-Token': self.token + 'x'}),
                 ('page without ?t=', '/', {}),
                 ('foreign Host', '/state', {'X-Rvu-Token': self.token,
                                             'Host': f'rvu.example.com:{self.port}'}),
                 ('foreign Origin', '/state', {'X-Rvu-Token': self.token,
                                               'Origin': 'http://example.com'})]
        for name, path, headers in cases:
            status, _, _ = http('GET', base + path, headers=headers, timeout=15)
            if status != 403:
                raise Fail(f'request with {name}: HTTP {status}, expected 403')
        status, _, _ = http('GET', base + '/state', headers={
            'X-Rvu-Token': self.token, 'Host': f'localhost:{self.port}',
            'Origin': f'http://localhost:{self.port}'}, timeout=15)
        if status != 200:
            raise Fail(f'request with Host and Origin localhost:{self.port}: HTTP {status}')
        ok('requests without the token or from another Host/Origin are refused (403)')

    def check_mouse(self):
        img = {ELEMENT: self.wd.element('#picture')}
        mouse = lambda *acts: {'type': 'pointer', 'id': 'mouse',
                               'parameters': {'pointerType': 'mouse'}, 'actions': list(acts)}
        at = lambda x, y: {'type': 'pointerMove', 'duration': 0, 'origin': img, 'x': x, 'y': y}
        down, up = {'type': 'pointerDown', 'button': 0}, {'type': 'pointerUp', 'button': 0}

        # A pick: "aim" without a point waits for a click on the picture.
        before, after = self.command('aim 1')
        if after['pick'] != '1' or not after['prompt']:
            raise Fail(f'"aim 1" did not ask for a pick: {after["log"][-3:]}')
        self.wd.actions(mouse(at(-20, 10), down, up))
        snap = self.wait('the picked "aim 1" to be answered',
                         lambda s: s['pick'] == '0' and s['commands'] > after['commands'], 30)
        if len(snap['errors']) > len(before['errors']):
            raise Fail(f'picked "aim 1" answered {snap["errors"][-1]!r}')
        ok(f'"aim 1" asks "{after["prompt"]}"; a click answers it')

        drag = {'type': 'pointerMove', 'duration': 250, 'origin': 'pointer', 'x': 80, 'y': -40}
        self.gesture('drag', 'pivot -', [mouse(at(0, 0), down, drag, up)])
        wheel = {'type': 'wheel', 'id': 'wheel', 'actions': [
            {'type': 'scroll', 'origin': img, 'x': 10, 'y': 10, 'deltaX': 0, 'deltaY': -120,
             'duration': 0}]}
        self.gesture('wheel', 'move 1.25', [wheel])
        time.sleep(0.3)  # well apart from the wheel notch and from earlier clicks
        self.gesture('double-click', 'aim 1.5',
                     [mouse(at(15, -15), down, up, {'type': 'pause', 'duration': 50}, down, up)])


def main():
    argv = sys.argv[1:]
    if '--' not in argv or argv.index('--') == len(argv) - 1:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    split = argv.index('--')
    ap = argparse.ArgumentParser()
    ap.add_argument('--screenshot', required=True, help='where to write the PNG screenshot')
    opts = ap.parse_args(argv[:split])
    cmd = argv[split + 1:]

    driver = shutil.which('chromedriver') or '/usr/bin/chromedriver'
    if not os.access(CHROMIUM, os.X_OK) or not os.access(driver, os.X_OK):
        print(f'SKIP: needs {CHROMIUM} and chromedriver (Debian: chromium, chromium-driver)')
        return 77

    start = time.monotonic()
    tmp = tempfile.mkdtemp(prefix='rvu_browser_')
    server = wd = None
    log = open(os.path.join(tmp, 'chromedriver.log'), 'wb')
    try:
        server = Server(cmd)
        url, port, token = server.wait_url(60)
        ok(f'server says {url.split("?")[0]}')
        wd = WebDriver(driver, log)
        wd.start(os.path.join(tmp, 'profile'))
        ok(f'chromedriver session started ({time.monotonic() - start:.1f} s)')
        Test(server, wd, url, port, token).run(opts.screenshot)
        print(f'PASS rvu browser test ({time.monotonic() - start:.1f} s)')
        return 0
    except Exception as e:  # any failure, ours or an unexpected one, is reported the same way
        print(f'FAIL: {e if isinstance(e, Fail) else repr(e)}', flush=True)
        if server and server.tail:
            print('server output (last lines):\n  ' + '\n  '.join(server.tail))
        return 1
    finally:
        if wd:
            wd.stop()
        if server:
            server.stop()
        log.close()
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
