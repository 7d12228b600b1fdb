// Runs before the game's main in the page: the assets' place, the arguments from the address,
// and the data folder (high scores, replays) kept in the browser's IndexedDB.
Module['preRun'] = Module['preRun'] || [];
Module['preRun'].push(function() {
  // The assets are packed at /assets (both names of the variable: POLARCADE_ASSETS is the one
  // the installable build reads).
  ENV['POLAR_ASSETS'] = '/assets';
  ENV['POLARCADE_ASSETS'] = '/assets';
  // /data is read back from IndexedDB before main starts, and written back a second after each
  // change is seen (and when the page is hidden or left), so a saved high score survives a reload.
  FS.mkdir('/data');
  FS.mount(IDBFS, {}, '/data');
  addRunDependency('polar-data');
  FS.syncfs(true, function(error) {
    if (error) console.error('polarcade: the saved data cannot be read back: ' + error);
    removeRunDependency('polar-data');
  });
  var writing = false;
  var writeBack = function() {
    if (writing) return;
    writing = true;
    FS.syncfs(false, function(error) {
      writing = false;
      if (error) console.error('polarcade: the data cannot be saved: ' + error);
      if (Module['onDataSaved']) Module['onDataSaved']();
    });
  };
  setInterval(writeBack, 1000);
  // A phone may close a hidden tab without a pagehide: hidden is the last sure moment.
  window.addEventListener('pagehide', writeBack);
  document.addEventListener('visibilitychange', function() { if (document.hidden) writeBack(); });
});

// ?lives=1&seed=5&mute → --lives 1 --seed 5 --mute
if (!Module['arguments'] && typeof location !== 'undefined') {
  var args = [];
  new URLSearchParams(location.search).forEach(function(value, key) {
    args.push('--' + key);
    if (value !== '') args.push(value);
  });
  Module['arguments'] = args;
}

// A replay file from the player, picked with "Open a replay" or dropped anywhere on the page, is
// copied into the page's file system and opened in the theatre (checked tick by tick, as natively).
function polarOpenReplayFile(file) {
  file.arrayBuffer().then(function(bytes) {
    FS.mkdirTree('/tmp/opened');
    var path = '/tmp/opened/' + file.name.replace(/[^A-Za-z0-9._-]/g, '_');
    FS.writeFile(path, new Uint8Array(bytes));
    Module.ccall('polar_web_open_replay', null, ['string'], [path]);
  });
}
if (typeof document !== 'undefined') {
  var polarWireReplayOpening = function() {
    var button = document.getElementById('open-replay'), input = document.getElementById('replay-file');
    if (button && input) {
      button.addEventListener('click', function() { input.click(); });
      input.addEventListener('change', function() {
        if (input.files.length) polarOpenReplayFile(input.files[0]);
        input.value = '';
      });
    }
    document.addEventListener('dragover', function(event) { event.preventDefault(); });
    document.addEventListener('drop', function(event) {
      event.preventDefault();
      if (event.dataTransfer && event.dataTransfer.files.length) polarOpenReplayFile(event.dataTransfer.files[0]);
    });
  };
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', polarWireReplayOpening);
  else polarWireReplayOpening();
}
