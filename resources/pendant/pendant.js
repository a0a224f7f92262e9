// The StepCom pendant page: shows what the window's status poll reads, sends the E-STOP, and
// jogs while a finger is held (a hold every 100 ms; StepCom stops the motor itself when holds
// stop coming). Plain script, nothing fetched from elsewhere.
'use strict';
(function () {
  const base = location.pathname.replace(/\/$/, '') + '/';
  const $ = (id) => document.getElementById(id);
  let words = {};
  let socket = null;
  let lastStatus = 0;
  let control = { allowed: false, you: false, holder: null };
  let held = null; // { motor, dir, button, timer }
  let closedForGood = false;

  const word = (key, fallback) => (words[key] !== undefined ? words[key] : fallback);

  function applyWords() {
    document.documentElement.lang = words.lang || 'en';
    document.title = word('title', document.title);
    document.querySelectorAll('[data-s]').forEach((el) => {
      el.textContent = word(el.dataset.s, el.textContent);
    });
    document.querySelectorAll('[data-aria]').forEach((el) => {
      let name = word(el.dataset.aria, el.getAttribute('aria-label'));
      if (el.dataset.motor) name = name.replace('%1', el.dataset.motor);
      el.setAttribute('aria-label', name);
    });
    renderControl();
  }

  function send(message) {
    if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
  }

  function notice(text) {
    const n = $('notice');
    n.textContent = text;
    n.hidden = !text;
    clearTimeout(notice.timer);
    if (text && !closedForGood) notice.timer = setTimeout(() => { n.hidden = true; }, 4000);
  }

  function renderStatus(s) {
    lastStatus = performance.now();
    document.body.classList.remove('stale');
    const dev = s.device || {};
    $('device').textContent = dev.name
      ? word('deviceNamed', '%1 (id %2)').replace('%1', dev.name).replace('%2', dev.id)
      : word('device', 'Device %1').replace('%1', dev.id);
    const link = $('link');
    link.textContent = word('link', 'Link') + ': ' + word(s.link, s.link);
    link.className = 'link ' + s.link;
    (s.motors || []).forEach((m) => {
      const pos = $('pos' + m.n);
      if (!pos) return;
      pos.textContent = m.position === null ? '—' : m.position;
      const st = $('state' + m.n);
      st.textContent = m.state === null ? '—' : word(m.state, m.state);
      st.className = 'state ' + (m.state || 'unknown');
      const ref = $('ref' + m.n);
      ref.textContent = word(m.referenced ? 'referenced' : 'notReferenced', '');
      ref.className = 'ref ' + (m.referenced ? 'yes' : 'no');
    });
    const lamps = (prefix, values) => (values || []).forEach((v, i) => {
      const el = $(prefix + (i + 1));
      if (el) el.className = 'lamp' + (v === null ? '' : v ? ' on' : ' off');
    });
    lamps('in', s.inputs);
    lamps('out', s.outputs);
  }

  function renderControl() {
    const mayJog = control.allowed && control.you;
    document.querySelectorAll('button.jog, button.step').forEach((b) => { b.disabled = !mayJog; });
    const take = $('take');
    take.disabled = !control.allowed;
    take.textContent = control.you ? word('giveBack', 'Give up control') : word('take', 'Take control');
    take.setAttribute('aria-label', take.textContent);
    $('controlText').textContent = !control.allowed ? word('watchOnly', '')
      : control.you ? word('youHold', '')
      : control.holder ? word('otherHolds', '%1').replace('%1', control.holder)
      : word('mayTake', '');
  }

  // Let go of a held jog: the message tells why; StepCom stops the motor anyway if it never comes.
  function letGo(why) {
    if (!held) return;
    clearInterval(held.timer);
    held.button.classList.remove('held');
    send({ t: 'stop', motor: held.motor, why: why });
    held = null;
  }

  function press(button, event) {
    if (button.disabled || held) return;
    event.preventDefault();
    try { button.setPointerCapture(event.pointerId); } catch (e) { /* not every pointer */ }
    const motor = Number(button.dataset.motor);
    held = { motor: motor, dir: button.dataset.dir, button: button, timer: 0 };
    button.classList.add('held');
    send({ t: 'jog', motor: motor, dir: button.dataset.dir });
    held.timer = setInterval(() => send({ t: 'hold', motor: motor }), 100);
  }

  document.querySelectorAll('button.jog').forEach((b) => {
    b.addEventListener('pointerdown', (e) => press(b, e));
    b.addEventListener('pointerup', () => letGo('lifted'));
    b.addEventListener('pointercancel', () => letGo('lifted'));
    b.addEventListener('lostpointercapture', () => letGo('lifted'));
    b.addEventListener('contextmenu', (e) => e.preventDefault());
  });
  document.querySelectorAll('button.step').forEach((b) => {
    b.addEventListener('click', () => send({
      t: 'step', motor: Number(b.dataset.motor), dir: b.dataset.dir, size: Number($('size').value),
    }));
  });
  document.addEventListener('visibilitychange', () => { if (document.hidden) letGo('hidden'); });
  window.addEventListener('blur', () => letGo('blur'));
  window.addEventListener('pagehide', () => letGo('hidden'));

  let lastEstop = 0;
  const estop = () => {
    const now = performance.now();
    if (now - lastEstop < 300) return; // a press is one stop, whether pointer or click
    lastEstop = now;
    letGo('lifted');
    send({ t: 'estop' });
  };
  $('estop').addEventListener('pointerdown', estop);
  $('estop').addEventListener('click', estop);
  $('take').addEventListener('click', () => send({ t: control.you ? 'give' : 'take' }));

  // Older than a second: nothing shown can be trusted, the page turns grey and says so.
  setInterval(() => {
    const age = lastStatus ? (performance.now() - lastStatus) / 1000 : Infinity;
    const stale = age > 1;
    document.body.classList.toggle('stale', stale);
    $('age').textContent = stale ? word('noData', 'no data') : word('age', 'updated %1 s ago').replace('%1', age.toFixed(1));
  }, 200);

  function connect() {
    const scheme = location.protocol === 'https:' ? 'wss://' : 'ws://';
    socket = new WebSocket(scheme + location.host + base + 'ws');
    socket.onopen = () => send({ t: 'hello', lang: navigator.language || 'en', ua: navigator.userAgent });
    socket.onmessage = (event) => {
      const m = JSON.parse(event.data);
      if (m.t === 'status') renderStatus(m);
      else if (m.t === 'control') { control = m; if (!m.you) letGo('lifted'); renderControl(); }
      else if (m.t === 'jog') {
        if (!m.jogging && held && held.motor === m.motor) letGo('lifted');
      } else if (m.t === 'refused') notice(m.text);
      else if (m.t === 'bye') { closedForGood = true; notice(m.text); }
    };
    socket.onclose = () => {
      letGo('lifted');
      control = { allowed: false, you: false, holder: null };
      renderControl();
      if (!closedForGood) notice(word('lost', 'Connection lost: reload the page'));
      closedForGood = true;
    };
  }

  fetch(base + 'strings.json').then((r) => r.json()).then((w) => { words = w; applyWords(); })
    .catch(() => {}).finally(connect);
  renderControl();
}());
