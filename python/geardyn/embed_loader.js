// geardyn's loader of the libraries its HTML pages embed compressed (python/geardyn/_embed.py):
// <script type="application/gzip-base64" id="..."> elements, unpacked with the browser's
// DecompressionStream. window.gdLib.text(id) -> Promise of the text; classic(id) runs it as a
// classic script (plotly.js); three() -> Promise of {THREE, OrbitControls} (three.js is a set of
// ES modules: each becomes a blob: URL and the imports between them are pointed at those).
window.gdLib = window.gdLib || (function () {
  'use strict';
  var texts = {}, times = {};
  function bytes(id) {
    var element = document.getElementById(id);
    if (!element) throw new Error('geardyn page: no embedded library ' + id);
    var binary = atob(element.textContent.trim());
    var out = new Uint8Array(binary.length);
    for (var i = 0; i < binary.length; ++i) out[i] = binary.charCodeAt(i);
    return out;
  }
  function text(id) {
    if (!texts[id]) {
      var stream = new Blob([bytes(id)]).stream().pipeThrough(new DecompressionStream('gzip'));
      texts[id] = new Response(stream).text();
    }
    return texts[id];
  }
  function classic(id) {
    return text(id).then(function (source) {
      var script = document.createElement('script');
      script.textContent = source;
      document.head.appendChild(script);
    });
  }
  function url(source) {
    return URL.createObjectURL(new Blob([source], {type: 'text/javascript'}));
  }
  var three = null;
  function loadThree() {
    if (!three) {
      three = Promise.all([text('gd-lib-three-core'), text('gd-lib-three-module'),
                           text('gd-lib-three-orbit')]).then(function (t) {
        var core = url(t[0]);
        var module = url(t[1].split('./three.core.min.js').join(core));
        var orbit = url(t[2].split("from 'three'").join("from '" + module + "'"));
        return Promise.all([import(module), import(orbit)]);
      }).then(function (m) {
        times.three = performance.now();
        return {THREE: m[0], OrbitControls: m[1].OrbitControls};
      });
    }
    return three;
  }
  return {text: text, classic: classic, three: loadThree, times: times};
})();
