// The --animate page's script (src/output/animation.cpp embeds it at build time): a frame sets one
// `transform` per link and per contact point from tables of strings built once from the data (rollkinData);
// nothing else of the document changes.
(function () {
  "use strict";
  var d = rollkinData, n = d.inputs.length;
  var svg = document.getElementById("mechanism");
  var slider = document.getElementById("pose"), button = document.getElementById("play");
  var valueOut = document.getElementById("input-value"), indexOut = document.getElementById("pose-index");
  var statusOut = document.getElementById("status");
  var links = [], contacts = [], l, c, k;
  for (l = 0; l < d.links; ++l) links.push(document.getElementById("link-" + l));
  for (c = 0; c < d.contacts; ++c) contacts.push(document.getElementById("contact-" + c));
  // Per pose, the transform of every link and contact point (null: the pose has no values).
  var linkT = [], contactT = [];
  for (k = 0; k < n; ++k) {
    var p = d.poses[k], q = d.contact_points[k], t = null, u = null;
    if (p !== null) {
      t = [];
      for (l = 0; l < d.links; ++l) t.push("translate(" + p[3 * l] + " " + p[3 * l + 1] + ") rotate(" + p[3 * l + 2] + ")");
      u = [];
      for (c = 0; c < d.contacts; ++c) u.push("translate(" + q[2 * c] + " " + q[2 * c + 1] + ")");
    }
    linkT.push(t);
    contactT.push(u);
  }
  var shown = -1, hidden = false;
  function setHidden(h) {
    if (h === hidden) return;
    hidden = h;
    for (l = 0; l < links.length; ++l) if (l !== d.ground) links[l].setAttribute("visibility", h ? "hidden" : "visible");
    for (c = 0; c < contacts.length; ++c) contacts[c].setAttribute("visibility", h ? "hidden" : "visible");
  }
  function show(i) {
    if (i === shown) return;
    shown = i;
    var t = linkT[i], u = contactT[i];
    if (t !== null) {
      for (l = 0; l < links.length; ++l) links[l].setAttribute("transform", t[l]);
      for (c = 0; c < contacts.length; ++c) contacts[c].setAttribute("transform", u[c]);
    }
    setHidden(t === null);
    valueOut.textContent = String(d.inputs[i]);
    indexOut.textContent = String(d.rows[i] + 1);
    statusOut.textContent = d.status_texts[d.status[i]];
    statusOut.className = d.status_kinds[d.status[i]];
    slider.value = String(i);
  }
  // Playing: about six seconds per sweep (10 to 60 poses per second), from the pose shown, looping.
  var rate = Math.min(60, Math.max(10, n / 6)), playing = false, t0 = null, from = 0;
  function tick(now) {
    if (!playing) return;
    if (t0 === null) t0 = now;
    show((from + Math.floor((now - t0) * rate / 1000)) % n);
    window.requestAnimationFrame(tick);
  }
  function setPlaying(on) {
    playing = on;
    button.textContent = on ? "Pause" : "Play";
    button.setAttribute("aria-pressed", on ? "true" : "false");
    if (on) {
      t0 = null;
      from = shown === n - 1 ? 0 : shown;
      window.requestAnimationFrame(tick);
    }
  }
  button.addEventListener("click", function () { setPlaying(!playing); });
  slider.addEventListener("input", function () { show(Number(slider.value)); t0 = null; from = shown; });
  var traces = document.getElementById("show-traces");  // (none without contact pairs)
  if (traces !== null) traces.addEventListener("change", function (e) { svg.classList.toggle("no-traces", !e.target.checked); });
  document.getElementById("show-centrodes").addEventListener("change", function (e) {
    svg.classList.toggle("no-centrodes", !e.target.checked);
  });
  show(d.start);
})();
