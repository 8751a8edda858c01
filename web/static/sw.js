// Edgewise's service worker: the app keeps working offline after one visit.
//
// The app shell (page, JavaScript, wasm, icon, example page) is cached under a
// name that carries the build's version, which `cargo xtask build-web` stamps
// in below. A new build therefore changes this file, the browser installs the
// new worker beside the old one, and the page offers to reload (index.html).
// The shell is served cache-first: the JavaScript and the wasm of one build
// must never be mixed with another's. Their names carry the build too, and
// the install fails (and the old worker stays) unless every file of this
// build is on the server, so an upload that is not atomic (sw.js and
// index.html before the JS and wasm) never mixes builds. Other files of the
// site (meshes linked with ?mesh=) go to the network first and fall back to a
// cached copy.

const BUILD = '__EDGEWISE_BUILD__';
const PREFIX = 'edgewise-';
const SHELL_CACHE = `${PREFIX}shell-${BUILD}`;
const FILES_CACHE = `${PREFIX}files-${BUILD}`;
const SHELL = [
  './',
  'index.html',
  `edgewise_app.${BUILD}.js`,
  `edgewise_app_bg.${BUILD}.wasm`,
  'favicon.svg',
  'examples/embed.html',
];

const scoped = (path) => new URL(path, self.registration.scope).href;

self.addEventListener('install', (event) => {
  // 'no-cache' revalidates with the server, so a stale HTTP cache cannot
  // slip an older wasm under this build's name.
  // A file missing from the server fails the install, and the old worker
  // stays in charge; its empty cache is not left behind.
  event.waitUntil(
    caches.open(SHELL_CACHE)
      .then((cache) =>
        cache.addAll(SHELL.map((path) => new Request(scoped(path), { cache: 'no-cache' }))))
      .catch(async (err) => {
        await caches.delete(SHELL_CACHE);
        throw err;
      }),
  );
  // No skipWaiting here: the page asks for it when the user chooses to reload.
});

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    const keep = new Set([SHELL_CACHE, FILES_CACHE]);
    const names = await caches.keys();
    await Promise.all(names
      .filter((name) => name.startsWith(PREFIX) && !keep.has(name))
      .map((name) => caches.delete(name)));
    await self.clients.claim();
  })());
});

self.addEventListener('message', (event) => {
  if (event.data === 'skipWaiting') {
    self.skipWaiting();
  }
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) {
    return;
  }
  const url = new URL(request.url);
  if (url.pathname.endsWith('/sw.js')) {
    return;
  }
  event.respondWith(respond(request, url));
});

async function respond(request, url) {
  const shell = await caches.open(SHELL_CACHE);
  // Links differ only in their query (?sample=cube&embed=1): one cached page.
  const cached = await shell.match(request, { ignoreSearch: request.mode === 'navigate' });
  if (cached) {
    return cached;
  }
  try {
    const response = await fetch(request);
    if (response.ok && url.search === '') {
      const files = await caches.open(FILES_CACHE);
      await files.put(request, response.clone());
    }
    return response;
  } catch (err) {
    const files = await caches.open(FILES_CACHE);
    const copy = await files.match(request);
    if (copy) {
      return copy;
    }
    throw err;
  }
}
