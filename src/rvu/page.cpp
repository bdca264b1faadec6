// rvu's display: the page the rvu process serves to a local browser. It long-polls
// /state, fetches /picture.png whenever the generation changes, and sends commands
// (typed, or made from mouse gestures) to /command. Every request carries the token
// from the page's own URL in X-Rvu-Token. Server text only ever goes in through
// textContent. The body's data-* attributes expose the page's state to the browser
// test (tests/browser/rvu_browser.py).
#include "rvu/page.h"

namespace rp::rvu {

namespace {

constexpr std::string_view kPage = R"rvu(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>rvu</title>
<link rel="icon" href="data:,"><!-- else the browser asks for /favicon.ico without the token -->
<style>
:root { color-scheme: dark; }
html, body { height: 100%; margin: 0; }
body {
    display: flex; flex-direction: column;
    background: #1c1c1c; color: #d8d8d8;
    font: 14px system-ui, sans-serif;
}
#stage {
    flex: 1 1 0; min-height: 0; overflow: hidden;
    display: flex; align-items: center; justify-content: center;
    background: #111;
}
#picture { user-select: none; -webkit-user-drag: none; cursor: grab; }
#picture.dragging { cursor: grabbing; }
#picture.picking { cursor: crosshair; }
#picture[hidden] { display: none; }
#panel { flex: 0 0 auto; padding: 6px 10px 8px; border-top: 1px solid #333; }
#status { display: flex; gap: 2em; white-space: nowrap; }
#status-text { flex: 1 1 auto; overflow: hidden; text-overflow: ellipsis; }
#exposure, #size { color: #aaa; }
#view {
    font: 12px ui-monospace, monospace; color: #8a8a8a; margin: 3px 0 5px;
    white-space: nowrap; overflow: hidden; text-overflow: ellipsis;
}
#prompt { color: #fc6; margin-bottom: 4px; }
#command {
    box-sizing: border-box; width: 100%; padding: 4px 6px;
    font: 14px ui-monospace, monospace; color: #eee;
    background: #101010; border: 1px solid #444; border-radius: 3px;
}
#command:focus { outline: none; border-color: #79a; }
#help { font-size: 12px; color: #777; margin: 3px 0 5px; }
#log {
    height: 8.5em; overflow-y: auto; padding: 2px 6px;
    font: 12px ui-monospace, monospace; white-space: pre-wrap;
    background: #151515; border: 1px solid #2a2a2a;
}
#log .cmd { color: #8bc4ee; }
#log .note { color: #888; }
#log .error { color: #ff6b6b; }
</style>
</head>
<body data-generation="-1" data-done="0" data-exposure="" data-ended="0" data-pick="0"
      data-commands="0">
<div id="stage"><img id="picture" alt="rvu picture" hidden></div>
<div id="panel">
<div id="status">
<span id="status-text">connecting&hellip;</span><span id="exposure"></span><span id="size"></span>
</div>
<div id="view"></div>
<div id="prompt" hidden></div>
<input id="command" autocomplete="off" spellcheck="false" autofocus
       placeholder="rvu command (e.g. exposure +1, view, quit)">
<div id="help">drag: pivot &middot; wheel: move &middot; double-click: aim (shift: away)
&middot; Up/Down: history &middot; commands as rvu(1)</div>
<div id="log" aria-live="polite"></div>
</div>
<script>
'use strict';
(() => {
const $ = (id) => document.getElementById(id);
const body = document.body;
const img = $('picture'), stage = $('stage'), logEl = $('log'), input = $('command');
const statusText = $('status-text'), exposureEl = $('exposure'), sizeEl = $('size');
const viewEl = $('view'), promptEl = $('prompt');
const token = new URLSearchParams(location.search).get('t') || '';
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

let state = null;               // the last /state answer
let shownGen = -1;              // generation of the picture on screen
let pictureUrl = null;          // its object URL, revoked when replaced
let pictureBusy = false;        // at most one picture fetch in flight
let pictureError = '';          // the last picture failure logged, not to repeat it
let ended = false;
let pick = null;                // pending pick: {line, text, points, cursor}
let lastPickAt = 0;
let queue = Promise.resolve();  // commands run one at a time, in order
let pendingCommands = 0;
let completed = 0;

function api(path, init = {}) {
    const headers = new Headers(init.headers || {});
    headers.set('X-Rvu-Token', token);
    return fetch(path, { ...init, headers, cache: 'no-store' });
}

function log(text, cls) {
    const line = document.createElement('div');
    line.className = cls;
    line.textContent = text;
    logEl.append(line);
    while (logEl.childElementCount > 500) logEl.firstElementChild.remove();
    logEl.scrollTop = logEl.scrollHeight;
}

const message = (e) => (e && e.message) ? e.message : String(e);

// ---- picture and state ----

function updateFlags() {
    body.dataset.generation = String(shownGen);
    body.dataset.done = state && state.done && shownGen === state.generation ? '1' : '0';
}

function formatExposure(e) {
    if (typeof e !== 'number' || !(e > 0)) return String(e);
    const stops = Math.log2(e);
    return `${+e.toPrecision(4)} (${stops >= 0 ? '+' : ''}${stops.toFixed(1)} stops)`;
}

function fit() {
    const w = img.naturalWidth, h = img.naturalHeight;
    if (!w || !h) return;
    const margin = 12;  // keeps the picture off the window's edge and the panel
    const k = Math.min((stage.clientWidth - margin) / w, (stage.clientHeight - margin) / h);
    if (!(k > 0)) return;
    img.style.width = `${Math.max(1, Math.floor(w * k))}px`;
    img.style.height = `${Math.max(1, Math.floor(h * k))}px`;
    // Nearest-neighbour shows rvu's refinement blocks honestly, but aliases when shrinking.
    img.style.imageRendering = k >= 1 ? 'pixelated' : 'auto';
}

function applyState(s) {
    if (ended) return;  // an answer still on its way must not overwrite "rvu has ended"
    state = s;
    body.dataset.exposure = String(s.exposure);
    statusText.textContent = String(s.status ?? '');
    exposureEl.textContent = `exposure ${formatExposure(s.exposure)}`;
    sizeEl.textContent = `${s.width} \u00d7 ${s.height}`;
    viewEl.textContent = String(s.view ?? '');
    viewEl.title = viewEl.textContent;
    updateFlags();
    if (s.quit) end();
    else if (s.generation > shownGen) loadPicture();
}

async function loadPicture() {
    if (pictureBusy) return;
    pictureBusy = true;
    try {
        while (!ended && state.generation > shownGen) {
            const want = state.generation;
            const r = await api(`/picture.png?g=${want}`);
            if (!r.ok) throw new Error(`picture: HTTP ${r.status} ${(await r.text()).trim()}`);
            const header = r.headers.get('X-Rvu-Generation');
            const url = URL.createObjectURL(await r.blob());
            img.src = url;
            try {
                await img.decode();
            } catch {
                log(`picture ${want} could not be decoded`, 'error');
            }
            if (pictureUrl) URL.revokeObjectURL(pictureUrl);
            pictureUrl = url;
            img.hidden = false;
            shownGen = Number.isFinite(Number(header ?? want)) ? Number(header ?? want) : want;
            pictureError = '';
            fit();
            updateFlags();
            if (shownGen < want) await sleep(200);  // server behind its own state: don't spin
        }
    } catch (e) {
        if (!ended) {
            if (message(e) !== pictureError) log(message(e), 'error');
            pictureError = message(e);
            await sleep(1000);
        }
    } finally {
        pictureBusy = false;
    }
    if (!ended && state.generation > shownGen) loadPicture();
}

async function poll() {
    let failures = 0;
    while (!ended) {
        try {
            const since = state ? `?since=${state.generation}` : '';
            const r = await api(`/state${since}`);
            if (!r.ok) throw new Error(`state: HTTP ${r.status} ${(await r.text()).trim()}`);
            const s = await r.json();
            failures = 0;
            applyState(s);
        } catch (e) {
            if (ended) break;
            // Say it once per outage; the status line shows that it goes on.
            if (++failures === 1) log(`no answer from rvu (${message(e)}); retrying`, 'error');
            statusText.textContent = 'no answer from rvu, retrying\u2026';
            await sleep(1000);
        }
    }
}

function end() {
    if (ended) return;
    ended = true;
    cancelPick();
    statusText.textContent = 'rvu has ended';
    body.dataset.ended = '1';
    input.disabled = true;
    input.placeholder = 'rvu has ended';
}

// ---- commands ----

function submit(line, cursor = null, echo = true) {
    pendingCommands++;
    queue = queue.then(() => runCommand(line, cursor, echo))
        .catch((e) => log(message(e), 'error'))  // a rejected queue would run no more commands
        .finally(() => pendingCommands--);
}

async function runCommand(line, cursor, echo) {
    if (ended) return;
    if (echo) log(`: ${line}`, 'cmd');
    try {
        const query = cursor ? `?cursor=${cursor.join(',')}` : '';
        let res;
        try {
            const r = await api(`/command${query}`, {
                method: 'POST', headers: { 'Content-Type': 'text/plain' }, body: line,
            });
            const text = await r.text();
            try {
                res = JSON.parse(text);
            } catch {
                throw new Error(r.ok ? `bad answer from rvu: ${text.slice(0, 200)}`
                                     : `HTTP ${r.status}: ${text.trim()}`);
            }
        } catch (e) {
            // rvu may close the connection as it quits: that is the quit succeeding.
            if (/^\s*quit\b/.test(line)) end();
            else if (e instanceof TypeError) log(`no answer from rvu (${message(e)})`, 'error');
            else log(message(e), 'error');
            return;
        }
        if (res.ok) {
            if (res.output) log(String(res.output).replace(/\n+$/, ''), 'out');
            if (res.quit) end();
        } else if (res.pick) {
            startPick(line, String(res.pick), Number(res.points) || 1);
        } else {
            log(String(res.error || 'command failed'), 'error');
        }
    } finally {
        body.dataset.commands = String(++completed);
    }
}

function startPick(line, text, points) {
    pick = { line, text, points: Math.max(1, Math.floor(points)), cursor: [] };
    showPrompt();
    body.dataset.pick = '1';
    img.classList.add('picking');
}

function showPrompt() {
    const more = pick.points > 1 ? ` (point ${pick.cursor.length / 2 + 1} of ${pick.points})` : '';
    promptEl.textContent = `${pick.text}${more}: click on the picture; Esc cancels`;
    promptEl.hidden = false;
}

function cancelPick(note) {
    if (!pick) return;
    pick = null;
    promptEl.hidden = true;
    body.dataset.pick = '0';
    img.classList.remove('picking');
    if (note) log(note, 'note');
}

function answerPick(point) {
    pick.cursor.push(...point);
    lastPickAt = performance.now();
    if (pick.cursor.length < 2 * pick.points) {
        showPrompt();
        return;
    }
    const { line, cursor } = pick;
    cancelPick();
    submit(line, cursor, false);
}

// ---- mouse ----

// Picture pixel under the mouse, y from the bottom (RADIANCE's convention).
function pixelAt(ev) {
    const r = img.getBoundingClientRect();
    const w = state.width, h = state.height;
    const clamp = (v, n) => Math.min(n - 1, Math.max(0, v));
    return [clamp(Math.floor((ev.clientX - r.left) * w / r.width), w),
            clamp(h - 1 - Math.floor((ev.clientY - r.top) * h / r.height), h)];
}

const round1 = (v) => Math.round(v * 10) / 10 + 0;  // + 0 turns -0 into 0
const usable = () => !ended && state && !img.hidden;

let press = null;  // mouse-down on the picture: {x, y, at, moved}
img.addEventListener('mousedown', (ev) => {
    if (ev.button !== 0 || !usable()) return;
    ev.preventDefault();  // no native image drag, no text selection
    press = { x: ev.clientX, y: ev.clientY, at: pixelAt(ev), moved: false };
});
window.addEventListener('mousemove', (ev) => {
    if (press && !press.moved && Math.hypot(ev.clientX - press.x, ev.clientY - press.y) > 4) {
        press.moved = true;
        if (!pick) img.classList.add('dragging');
    }
});
window.addEventListener('mouseup', (ev) => {
    if (!press || ev.button !== 0) return;
    const p = press;
    press = null;
    img.classList.remove('dragging');
    const moved = p.moved || Math.hypot(ev.clientX - p.x, ev.clientY - p.y) > 4;
    if (pick) {
        if (!moved) answerPick(p.at);
        return;
    }
    if (!moved || !usable()) return;
    // Signs make the scene turn with the mouse: dragging right orbits the eye to the left.
    const r = img.getBoundingClientRect();
    const angle = round1(-180 * (ev.clientX - p.x) / r.width);
    const elev = round1(90 * (p.y - ev.clientY) / r.height);
    submit(`pivot ${angle} ${elev}`, p.at);
});

let lastWheel = -1e9;
img.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    if (!usable() || pick || ev.deltaY === 0) return;
    // One command per 150 ms, and none while moves pile up behind a slow server.
    const now = performance.now();
    if (now - lastWheel < 150 || pendingCommands > 1) return;
    lastWheel = now;
    submit(ev.deltaY < 0 ? 'move 1.25' : 'move -1.25', pixelAt(ev));
}, { passive: false });

img.addEventListener('dblclick', (ev) => {
    ev.preventDefault();
    // The clicks of a double-click may have just answered a pick.
    if (!usable() || pick || performance.now() - lastPickAt < 600) return;
    submit(ev.shiftKey ? 'aim -1.5' : 'aim 1.5', pixelAt(ev));
});

new ResizeObserver(fit).observe(stage);

// ---- keyboard ----

const past = [];  // command history
let historyPos = 0;
let draft = '';

input.addEventListener('keydown', (ev) => {
    if (ev.key === 'Enter') {
        ev.preventDefault();
        const line = input.value.trim();
        input.value = '';
        draft = '';
        if (!line || ended) return;
        if (past[past.length - 1] !== line) past.push(line);
        historyPos = past.length;
        cancelPick('pick cancelled');  // a new command replaces the unanswered one
        submit(line);
    } else if (ev.key === 'ArrowUp' || ev.key === 'ArrowDown') {
        ev.preventDefault();
        if (ev.key === 'ArrowUp' && historyPos > 0) {
            if (historyPos === past.length) draft = input.value;
            input.value = past[--historyPos];
        } else if (ev.key === 'ArrowDown' && historyPos < past.length) {
            input.value = ++historyPos === past.length ? draft : past[historyPos];
        }
        input.setSelectionRange(input.value.length, input.value.length);
    }
});

document.addEventListener('keydown', (ev) => {
    if (ev.key === 'Escape' && pick) {
        ev.preventDefault();
        cancelPick('pick cancelled');
    }
});

if (!token) log('no token in the address: open the link rvu printed', 'error');
input.focus();
poll();
})();
</script>
</body>
</html>
)rvu";

}  // namespace

std::string_view pageHtml() { return kPage; }

}  // namespace rp::rvu
