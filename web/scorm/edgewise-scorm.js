// Edgewise's SCORM runtime (docs/lms.md), run by a package's launch.html.
//
// It finds the LMS's API as ADL's algorithm does, frames the package's copy
// of Edgewise, and speaks the embed protocol with it (docs/embedding.md):
// it starts each exercise, hears each graded step, and reports to the LMS
// the set's score and status, one interaction per graded action, and the
// attempts (kept in suspend_data, so a student who closes the tab comes back
// to the same instances and progress). Every LMS call's error code is
// checked and reported in the console and in edgewisePackage.state().lms.
// Without an LMS the page still works, and says once that nothing is kept.
(function () {
  'use strict';

  const config = JSON.parse(document.getElementById('edgewise-package').textContent);
  const v12 = config.scorm === '1.2';
  // cmi.suspend_data holds 4,096 characters in 1.2 and 64,000 in 2004.
  const SUSPEND_LIMIT = v12 ? 4096 : 64000;
  const SUSPEND_VERSION = 'E1';
  // How far up the frames the API is looked for: deep LMS frame sets stay
  // well inside this, and a loop of frames ends.
  const MAX_LEVELS = 500;
  const MAX_ERRORS = 50;
  const RESPONSE_CHARS = v12 ? 255 : 4000;
  const frame = document.getElementById('edgewise-frame');
  const list = document.getElementById('edgewise-items');
  const totalLine = document.getElementById('edgewise-total');
  const lmsLine = document.getElementById('edgewise-lms');

  const CALLS = v12
    ? { initialize: 'LMSInitialize', terminate: 'LMSFinish', get: 'LMSGetValue', set: 'LMSSetValue',
      commit: 'LMSCommit', lastError: 'LMSGetLastError', errorString: 'LMSGetErrorString',
      diagnostic: 'LMSGetDiagnostic' }
    : { initialize: 'Initialize', terminate: 'Terminate', get: 'GetValue', set: 'SetValue',
      commit: 'Commit', lastError: 'GetLastError', errorString: 'GetErrorString',
      diagnostic: 'GetDiagnostic' };
  const CMI = v12
    ? { entry: 'cmi.core.entry', exit: 'cmi.core.exit', location: 'cmi.core.lesson_location',
      sessionTime: 'cmi.core.session_time', score: 'cmi.core.score.' }
    : { entry: 'cmi.entry', exit: 'cmi.exit', location: 'cmi.location',
      sessionTime: 'cmi.session_time', score: 'cmi.score.' };

  // ---- The LMS -------------------------------------------------------

  const lms = { version: config.scorm, found: false, initialized: false, terminated: false, errors: [] };
  let api = null;

  // ADL's search: this window and its parents, then the opener's.
  function searchUp(win) {
    const name = v12 ? 'API' : 'API_1484_11';
    for (let level = 0; win && level <= MAX_LEVELS; level += 1) {
      try {
        if (win[name]) return win[name];
      } catch (err) {
        // Another site's frame: look further up.
      }
      if (win.parent === win) break;
      win = win.parent;
    }
    return null;
  }

  function report(call, element, code, message) {
    const error = { call: CALLS[call], element: element ?? null, code: String(code), message };
    lms.errors.push(error);
    if (lms.errors.length > MAX_ERRORS) lms.errors.shift();
    console.warn(`Edgewise: the LMS refused ${error.call}(${element === undefined ? '' : JSON.stringify(element)}): error ${code}: ${message}`);
  }

  // One LMS call, its error code checked.
  function lmsCall(call, element, value) {
    if (!api || lms.terminated) return '';
    let result;
    try {
      const method = api[CALLS[call]];
      result = value !== undefined ? method.call(api, element, value)
        : element !== undefined ? method.call(api, element)
          : method.call(api, '');
    } catch (err) {
      report(call, element, 'exception', err && err.message ? err.message : String(err));
      return '';
    }
    let code = '0';
    try {
      code = String(api[CALLS.lastError]());
    } catch (err) {
      code = 'exception';
    }
    // 2004's 403 is a value the LMS was never given: a first launch's
    // suspend_data, which is expected.
    if (code !== '0' && !(call === 'get' && code === '403')) {
      let message = '';
      try {
        message = String(api[CALLS.errorString](code));
        const diagnostic = String(api[CALLS.diagnostic](code));
        if (diagnostic && diagnostic !== message) message += ` (${diagnostic})`;
      } catch (err) {
        // The message is only for the console.
      }
      report(call, element, code, message);
    }
    return result === undefined || result === null ? '' : String(result);
  }

  const set = (element, value) => lmsCall('set', element, String(value));
  const get = (element) => lmsCall('get', element);

  // ---- The items -----------------------------------------------------

  const items = config.items.map((item) => Object.assign({}, item, {
    // Saved attempt (exerciseProgress()), the best finished score, and
    // whether an attempt is over.
    progress: '', best: 0, bestMax: 0, finished: false, started: false,
  }));
  const exercises = items.filter((item) => item.kind === 'exercise');
  let current = -1;
  let interactions = 0;
  let dropWarned = false;
  const started = Date.now();
  const texts = new Map();

  const ratio = (item) => (item.bestMax > 0 ? item.best / item.bestMax : 0);

  // The set's total: each exercise counts the same, by its best finished
  // attempt; views do not count.
  function total() {
    if (exercises.length === 0) return null;
    const sum = exercises.reduce((acc, item) => acc + (item.finished ? ratio(item) : 0), 0);
    return Math.round((10000 * sum) / exercises.length) / 100;
  }

  function summary() {
    const score = total();
    const completed = exercises.every((item) => item.finished);
    const passed = score !== null && score >= config.passMark;
    return { score, completed, passed };
  }

  // ---- Saving ----------------------------------------------------------

  function suspendText() {
    const write = () => [SUSPEND_VERSION, current, interactions].concat(items.map((item) => (
      item.kind === 'view' ? '' : [item.best, item.bestMax, (item.finished ? 'f' : '') + (item.started ? 's' : ''), item.progress].join('~')
    ))).join('|');
    let text = write();
    // Over 1.2's limit: drop the tables of the largest unfinished do-it
    // attempts first; a score is never dropped.
    const droppable = items.filter((item) => item.progress && !item.finished)
      .sort((a, b) => b.progress.length - a.progress.length);
    while (text.length > SUSPEND_LIMIT && droppable.length > 0) {
      const item = droppable.shift();
      if (!dropWarned) {
        console.warn(`Edgewise: the saved attempts pass SCORM ${config.scorm}'s ${SUSPEND_LIMIT} characters; the progress of "${item.title}" is not kept (its score is)`);
        dropWarned = true;
      }
      const keep = item.progress;
      item.progress = '';
      text = write();
      item.progress = keep;
    }
    return text;
  }

  function restore(saved) {
    const parts = saved.split('|');
    if (parts[0] !== SUSPEND_VERSION || parts.length !== items.length + 3) {
      if (saved) console.warn('Edgewise: the saved attempt is from another version of this package; starting afresh');
      return 0;
    }
    items.forEach((item, i) => {
      if (item.kind === 'view') return;
      const [best, bestMax, flags, progress] = parts[i + 3].split('~');
      item.best = Number(best) || 0;
      item.bestMax = Number(bestMax) || 0;
      item.finished = (flags || '').includes('f');
      item.started = (flags || '').includes('s');
      item.progress = /^[A-Za-z0-9:,.=+@;-]*$/.test(progress || '') ? progress : '';
    });
    interactions = Math.max(interactions, Number(parts[2]) || 0);
    const at = Number(parts[1]);
    return Number.isInteger(at) && at >= 0 && at < items.length ? at : 0;
  }

  // Score, status and the saved attempts; committed after graded actions.
  function save(commit) {
    render();
    if (!lms.initialized) return;
    const { score, completed, passed } = summary();
    if (score !== null) {
      set(CMI.score + 'min', 0);
      set(CMI.score + 'max', 100);
      set(CMI.score + 'raw', score);
      if (!v12) set('cmi.score.scaled', Math.round(score * 100) / 10000);
    }
    if (v12) {
      let status = 'incomplete';
      if (score === null) status = 'completed';
      else if (passed) status = 'passed';
      else if (completed) status = 'failed';
      set('cmi.core.lesson_status', status);
    } else {
      set('cmi.completion_status', completed ? 'completed' : 'incomplete');
      set('cmi.success_status', score === null ? 'unknown' : passed ? 'passed' : completed ? 'failed' : 'unknown');
      const finished = exercises.filter((item) => item.finished).length;
      set('cmi.progress_measure', exercises.length ? finished / exercises.length : 1);
    }
    set(CMI.location, current);
    set('cmi.suspend_data', suspendText());
    if (commit) lmsCall('commit');
  }

  const pad = (n, width = 2) => String(n).padStart(width, '0');

  // One record per graded action, so the gradebook shows what was done.
  function interaction(item, detail) {
    const n = interactions;
    interactions += 1;
    const at = `cmi.interactions.${n}.`;
    const now = new Date();
    const id = `${item.name}-${detail.attempt}-${detail.step}`;
    const result = detail.responseCorrect === null || detail.responseCorrect === undefined
      ? 'neutral' : detail.responseCorrect ? 'correct' : (v12 ? 'wrong' : 'incorrect');
    const response = String(detail.response).slice(0, RESPONSE_CHARS);
    set(at + 'id', id);
    set(at + 'type', v12 ? 'fill-in' : 'other');
    if (v12) {
      set(at + 'time', `${pad(now.getHours())}:${pad(now.getMinutes())}:${pad(now.getSeconds())}`);
      set(at + 'student_response', response);
    } else {
      set(at + 'timestamp', `${now.getFullYear()}-${pad(now.getMonth() + 1)}-${pad(now.getDate())}T${pad(now.getHours())}:${pad(now.getMinutes())}:${pad(now.getSeconds())}`);
      set(at + 'description', `${item.title}: ${response}`.slice(0, 250));
      set(at + 'learner_response', response);
    }
    set(at + 'result', result);
  }

  // ---- The app in the frame ------------------------------------------

  let generation = 0;
  // The generation whose exercise the app shows: until its start is done,
  // the app still shows the last item's, whose attempt must not be kept
  // as this item's (a write then a quick switch did that).
  let shown = -1;
  let frameHref = '';
  let ready = null;
  let whenReady = () => {};
  const pending = new Map();
  let nextCall = 1;
  const target = () => (location.origin === 'null' ? '*' : location.origin);

  function callApp(method, ...args) {
    return new Promise((resolve, reject) => {
      const id = nextCall;
      nextCall += 1;
      pending.set(id, { resolve, reject });
      frame.contentWindow.postMessage({ type: 'edgewise:call', id, method, args }, target());
    });
  }

  function load(href) {
    frameHref = href;
    ready = new Promise((resolve) => { whenReady = resolve; });
    frame.src = href;
  }

  async function exerciseText(item) {
    if (!texts.has(item.file)) {
      const response = await fetch(item.file);
      if (!response.ok) throw new Error(`${item.file}: ${response.status} ${response.statusText}`);
      texts.set(item.file, await response.text());
    }
    return texts.get(item.file);
  }

  // The current item, if it is an exercise and the app shows it: only then
  // is the app's attempt this item's.
  function exerciseShown() {
    const item = items[current];
    return item && item.kind === 'exercise' && shown === generation ? item : null;
  }

  // Keeps the exercise on screen's attempt, as the app saves it.
  async function keepProgress() {
    const item = exerciseShown();
    const mine = generation;
    if (!item || !ready) return;
    try {
      const progress = await callApp('exerciseProgress');
      if (mine === generation && typeof progress === 'string') item.progress = progress;
    } catch (err) {
      console.warn('Edgewise: the attempt could not be read:', err.message);
    }
  }

  async function open(i) {
    if (i === current || i < 0 || i >= items.length) return;
    await keepProgress();
    generation += 1;
    current = i;
    const item = items[i];
    save(false);
    if (item.kind === 'view') {
      load(item.href);
      return;
    }
    const page = 'index.html?embed=1';
    if (frameHref !== page) load(page);
    await ready;
    const mine = generation;
    try {
      const text = await exerciseText(item);
      if (mine !== generation) return;
      try {
        const options = { name: item.name };
        if (item.progress) options.progress = item.progress;
        await callApp('startExercise', text, options);
      } catch (err) {
        // A saved attempt the app cannot bring back: a fresh instance.
        console.warn(`Edgewise: "${item.title}" starts afresh: ${err.message}`);
        item.progress = '';
        await callApp('startExercise', text, { name: item.name });
      }
      if (mine !== generation) return;
      shown = mine;
      await keepProgress();
      save(true);
    } catch (err) {
      console.error(`Edgewise: "${item.title}" could not start:`, err);
    }
  }

  let keepTimer = 0;
  window.addEventListener('message', (event) => {
    if (event.source !== frame.contentWindow) return;
    const data = event.data;
    if (!data || typeof data !== 'object' || typeof data.type !== 'string') return;
    const item = items[current];
    switch (data.type) {
      case 'edgewise:reply': {
        const call = pending.get(data.id);
        if (!call) return;
        pending.delete(data.id);
        if (data.ok) call.resolve(data.value);
        else call.reject(new Error(data.error));
        break;
      }
      case 'edgewise:ready':
        whenReady();
        break;
      case 'edgewise:exercisestart':
        if (item && item.kind === 'exercise') item.started = true;
        break;
      case 'edgewise:exercisestep':
        if (item && item.kind === 'exercise') graded(item, data);
        break;
      case 'edgewise:meshchange':
        // A write by hand is kept without a commit; graded steps commit.
        clearTimeout(keepTimer);
        keepTimer = setTimeout(() => keepProgress().then(() => save(false)), 400);
        break;
      default:
    }
  });

  let lastAction = '';
  async function graded(item, detail) {
    const mine = generation;
    item.started = true;
    const key = [detail.attempt, detail.step, detail.response, detail.finished].join('|');
    if (detail.response !== null && detail.response !== undefined && key !== lastAction && lms.initialized) {
      interaction(item, detail);
    }
    lastAction = key;
    if (detail.finished) {
      const score = Number(detail.score) || 0;
      const max = Number(detail.maxScore) || 0;
      const better = max > 0 && (!item.finished || score / max > ratio(item));
      if (better || !item.finished) {
        item.best = score;
        item.bestMax = max;
      }
      item.finished = true;
    }
    await keepProgress();
    if (mine === generation) save(true);
  }

  // ---- The page --------------------------------------------------------

  function render() {
    list.replaceChildren(...items.map((item, i) => {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.type = 'button';
      const title = document.createElement('span');
      title.textContent = item.title;
      const mark = document.createElement('span');
      mark.className = 'edgewise-mark';
      if (item.kind === 'view') mark.textContent = 'view';
      else if (item.finished) mark.textContent = `${item.best}/${item.bestMax}`;
      else mark.textContent = item.started ? 'started' : 'to do';
      button.append(title, mark);
      if (i === current) button.setAttribute('aria-current', 'true');
      button.addEventListener('click', () => open(i));
      li.append(button);
      return li;
    }));
    const { score, passed } = summary();
    totalLine.textContent = score === null ? ''
      : `Total ${score}% · pass mark ${config.passMark}%${passed ? ' · passed' : ''}`;
  }

  function sessionTime() {
    const seconds = Math.max(0, Math.round((Date.now() - started) / 1000));
    const h = Math.floor(seconds / 3600);
    const m = Math.floor((seconds % 3600) / 60);
    const s = seconds % 60;
    return v12 ? `${pad(Math.min(h, 9999), 4)}:${pad(m)}:${pad(s)}` : `PT${h}H${m}M${s}S`;
  }

  function terminate() {
    if (!lms.initialized || lms.terminated) return;
    // The frame is this site's: its attempt can be read at once.
    try {
      const item = exerciseShown();
      const progress = frame.contentWindow.edgewise?.exerciseProgress?.();
      if (item && typeof progress === 'string') item.progress = progress;
    } catch (err) {
      // Keep the last attempt read.
    }
    save(false);
    const { completed } = summary();
    set(CMI.exit, completed ? (v12 ? '' : 'normal') : 'suspend');
    set(CMI.sessionTime, sessionTime());
    lmsCall('commit');
    lmsCall('terminate');
    lms.terminated = true;
  }

  // The copy of the app in the frame registers no offline worker: the LMS
  // serves the package (index.html checks for this).
  window.edgewisePackage = {
    state: () => ({
      lms: Object.assign({}, lms, { errors: lms.errors.slice() }),
      current,
      items: items.map((item) => ({
        kind: item.kind, title: item.title, name: item.name ?? null, started: item.started,
        finished: item.finished, best: item.best, bestMax: item.bestMax,
      })),
      ...summary(),
    }),
    open,
  };

  function start() {
    api = searchUp(window) ?? (window.opener ? searchUp(window.opener) : null);
    lms.found = api !== null;
    let at = 0;
    if (api) {
      lms.initialized = lmsCall('initialize') === 'true';
      if (lms.initialized) {
        interactions = Number(get('cmi.interactions._count')) || 0;
        at = restore(get('cmi.suspend_data'));
        if (v12 && get('cmi.core.lesson_status') === 'not attempted') set('cmi.core.lesson_status', 'incomplete');
        window.addEventListener('pagehide', terminate);
      } else {
        lmsLine.textContent = 'The LMS did not start this attempt: nothing is recorded (see the console).';
      }
    } else {
      lmsLine.textContent = 'No LMS found: this page runs on its own, and nothing is recorded.';
      console.info(`Edgewise: no SCORM ${config.scorm} API (${v12 ? 'API' : 'API_1484_11'}) in this window, its parents or its opener; running as a plain page`);
    }
    render();
    open(at);
  }

  start();
}());
