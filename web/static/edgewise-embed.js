// edgewise-embed.js: live Edgewise views in any page, without a build step.
//
//   <div data-edgewise="https://example.edu/edgewise/?sample=cube&embed=1"
//        data-title="The cube's half-edges"></div>
//   <script src="https://example.edu/edgewise/edgewise-embed.js"></script>
//
// Each such element becomes a titled iframe that sizes itself to the height
// the view asks for (the edgewise:resize message). The element gets an
// `edgewise` object:
//
//   view.call('step', 2)          -> Promise of the result of window.edgewise.step(2)
//   view.on('stepchange', (m) => console.log(m.trace && m.trace.step))
//   view.ready                    -> Promise, settled when the view has started
//
// and every message is also dispatched on the element as a DOM event named
// after its type ('edgewise:stepchange'). Optional attributes:
// data-height (the first height, in CSS pixels, before the view asks),
// data-lazy="false" (load at once rather than when scrolled near), and
// data-title. Views added later are mounted by EdgewiseEmbed.scan().
(function () {
  'use strict';
  if (window.EdgewiseEmbed) return;

  const MIN_HEIGHT = 160;
  const MAX_HEIGHT = 2000;
  const views = [];

  function describe(url) {
    const sample = url.searchParams.get('sample');
    const algorithm = url.searchParams.get('algorithm');
    const parts = ['Edgewise'];
    if (sample) parts.push(sample);
    if (algorithm) parts.push(algorithm);
    return parts.join(': ') + ' (interactive mesh view)';
  }

  function mount(element) {
    if (element.edgewise) return element.edgewise;
    let url;
    try {
      url = new URL(element.getAttribute('data-edgewise') || '', document.baseURI);
    } catch (err) {
      element.textContent = 'Edgewise: this view\'s link is not a URL.';
      return null;
    }
    if (url.protocol !== 'https:' && url.protocol !== 'http:') {
      element.textContent = 'Edgewise: a view\'s link must start with https: or http:.';
      return null;
    }
    if (!url.searchParams.has('embed')) url.searchParams.set('embed', '1');

    const iframe = document.createElement('iframe');
    iframe.src = url.href;
    iframe.title = element.getAttribute('data-title') || describe(url);
    iframe.setAttribute('allow', 'fullscreen');
    if (element.getAttribute('data-lazy') !== 'false') iframe.loading = 'lazy';
    const first = parseInt(element.getAttribute('data-height') || '', 10);
    iframe.style.cssText = 'display:block;width:100%;border:0;height:' +
      (first >= MIN_HEIGHT && first <= MAX_HEIGHT ? first : 480) + 'px';
    element.replaceChildren(iframe);

    let nextId = 1;
    const pending = new Map();
    const listeners = new Map();
    let ready;
    const view = {
      element: element,
      iframe: iframe,
      origin: url.origin,
      ready: new Promise((resolve) => { ready = resolve; }),
      // Calls window.edgewise[method](...args) in the view.
      call: function (method) {
        const args = Array.prototype.slice.call(arguments, 1);
        return new Promise((resolve, reject) => {
          const id = nextId++;
          pending.set(id, { resolve: resolve, reject: reject });
          iframe.contentWindow.postMessage(
            { type: 'edgewise:call', id: id, method: String(method), args: args }, view.origin);
        });
      },
      // Listens for one kind of message ('stepchange', 'resize', …).
      on: function (name, listener) {
        if (!listeners.has(name)) listeners.set(name, []);
        listeners.get(name).push(listener);
        return view;
      },
      receive: function (message) {
        if (message.type === 'edgewise:reply') {
          const call = pending.get(message.id);
          if (!call) return;
          pending.delete(message.id);
          if (message.ok) call.resolve(message.value);
          else call.reject(new Error(String(message.error)));
          return;
        }
        const name = message.type.slice('edgewise:'.length);
        if (name === 'resize' && typeof message.height === 'number') {
          const height = Math.max(MIN_HEIGHT, Math.min(MAX_HEIGHT, Math.round(message.height)));
          iframe.style.height = height + 'px';
        }
        if (name === 'ready') ready(message);
        for (const listener of listeners.get(name) || []) {
          try { listener(message); } catch (err) { console.error(err); }
        }
        element.dispatchEvent(new CustomEvent(message.type, { detail: message }));
      },
    };
    element.edgewise = view;
    views.push(view);
    return view;
  }

  window.addEventListener('message', (event) => {
    const message = event.data;
    if (!message || typeof message !== 'object' || typeof message.type !== 'string' ||
        message.type.indexOf('edgewise:') !== 0) return;
    for (const view of views) {
      if (view.iframe.contentWindow === event.source && view.origin === event.origin) {
        view.receive(message);
        return;
      }
    }
  });

  function scan(root) {
    const found = (root || document).querySelectorAll('[data-edgewise]');
    return Array.prototype.map.call(found, mount).filter(Boolean);
  }

  window.EdgewiseEmbed = { views: views, mount: mount, scan: scan };
  // The elements above this script are mounted now, so a script after it
  // can use them; the rest once the page has loaded.
  scan();
  if (document.readyState === 'loading') {
    document.addEventListener('DOMContentLoaded', () => scan());
  }
})();
