// The page's service worker: every file of the bundle is kept in a cache at the first visit, and
// each request goes to the network first (so a new build is seen at once), falling back to the
// cache when the network is gone, so the game loads and plays offline after one visit.
var CACHE = 'polarcade';
var BUNDLE = ['./', 'index.html', 'polarcade.js', 'polarcade.wasm', 'polarcade.data'];

self.addEventListener('install', function(event) {
  event.waitUntil(caches.open(CACHE).then(function(cache) { return cache.addAll(BUNDLE); }).then(function() {
    return self.skipWaiting();
  }));
});

self.addEventListener('activate', function(event) {
  event.waitUntil(self.clients.claim());
});

self.addEventListener('fetch', function(event) {
  var request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(fetch(request).then(function(response) {
    if (response.ok) {
      var copy = response.clone();
      caches.open(CACHE).then(function(cache) { return cache.put(request, copy); });
    }
    return response;
  }).catch(function() {
    // The page's address carries its arguments (?lives=1): any cached copy of the page will do.
    return caches.match(request, { ignoreSearch: true }).then(function(cached) {
      return cached || Response.error();
    });
  }));
});
