#include "dcel/diff/report_html_assets.hpp"

namespace dcel::diff {

std::string_view html_report_style() {
    return R"CSS(
body { margin: 0 auto; max-width: 1500px; padding: 0 20px 40px; color: #1f2328; background: #f6f8fa;
  font: 15px/1.45 system-ui, "DejaVu Sans", sans-serif; }
code, pre { font: 13px "DejaVu Sans Mono", Menlo, Consolas, monospace; }
h1 { font-size: 22px; margin: 0; } h2 { font-size: 19px; margin: 0 0 8px; } h3 { font-size: 15px; margin: 14px 0 4px; }
.card { background: #fff; border: 1px solid #d0d7de; border-radius: 8px; padding: 14px 18px; margin: 14px 0; }
.verdict { margin-top: 20px; border-left: 8px solid #1a7f37; }
.verdict.fail { border-left-color: #b42318; } .verdict.empty { border-left-color: #9a6700; }
section.failure { border-top: 5px solid #b42318; }
dl { display: grid; grid-template-columns: max-content minmax(0, 1fr); gap: 2px 14px; margin: 0; }
dt { color: #59636e; } dd { margin: 0; overflow-wrap: anywhere; }
.grid { display: grid; grid-template-columns: minmax(0, 3fr) minmax(320px, 2fr); gap: 18px; align-items: start; }
.cols { display: grid; grid-template-columns: 1fr 1fr; gap: 18px; }
.grid > *, .cols > * { min-width: 0; }
figure { margin: 0; }
figure svg { display: block; width: 100%; height: auto; border: 1px solid #d0d7de; border-radius: 6px; }
figcaption, .quiet { color: #59636e; font-size: 13px; }
pre { margin: 4px 0 8px; padding: 6px 9px; background: #f6f8fa; border: 1px solid #d0d7de; border-radius: 6px;
  white-space: pre-wrap; overflow-wrap: anywhere; max-height: 22em; overflow: auto; }
pre.cmd { background: #1f2328; color: #f6f8fa; }
.esc { background: #ffe08a; color: #6b3f00; border-radius: 3px; }
.cut { color: #9a6700; font-style: italic; }
.kind { font: 600 12px monospace; color: #b42318; background: #fef3f2; border-radius: 4px; padding: 0 4px; }
.ref h3 { color: #2166ac; } .ans h3 { color: #d7191c; }
ol, ul { padding-left: 26px; margin: 4px 0; }
.walk { cursor: pointer; border-radius: 4px; }
.walk:hover, .walk:focus, .walk.pinned { background: #ffe3a3; outline: 2px solid #f5a623; }
#tip { position: absolute; pointer-events: none; transform: translate(-50%, calc(-100% - 8px)); background: #1f2328;
  color: #fff; font: 13px monospace; padding: 4px 8px; border-radius: 4px; white-space: nowrap; }
svg .hit { fill: transparent; cursor: crosshair; }
svg .ring { fill: none; stroke: #f5a623; stroke-width: 3; }
svg .hl { fill: none; stroke: #f5a623; stroke-width: 6; stroke-linecap: round; opacity: .75; stroke-dasharray: 12 6; }
svg .hl.answer { stroke: #d7191c; } svg .hl.reference { stroke: #2166ac; } svg .hl.jump { stroke-dasharray: 2 6; }
svg .hit, svg .ring, svg .hl { pointer-events: none; } svg .hit { pointer-events: all; }
@media (max-width: 1000px) { .grid, .cols { grid-template-columns: minmax(0, 1fr); } }
)CSS";
}

std::string_view html_report_script() {
    return R"JS(
(function () {
  "use strict";
  var NS = "http://www.w3.org/2000/svg", tip = document.getElementById("tip");
  function ids(text) { return (text || "").split(" ").filter(Boolean).map(Number); }
  function make(name, attrs, parent) {
    var e = document.createElementNS(NS, name);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    return parent.appendChild(e);
  }
  function setUp(section) {
    var svg = section.querySelector("figure svg");
    if (!svg) return;
    var flat = ids(section.getAttribute("data-edges")), edge = new Map();
    for (var e = 0; 2 * e + 1 < flat.length; ++e) {
      edge.set(flat[2 * e] + " " + flat[2 * e + 1], {e: e, back: false});
      edge.set(flat[2 * e + 1] + " " + flat[2 * e], {e: e, back: true});
    }
    // Each panel: where its vertices are, its edges' paths, a layer to draw on.
    var panels = ["reference", "answer"].map(function (name) {
      var g = svg.querySelector('[data-id="' + name + '"]');
      if (!g) return null;
      var p = {at: [], edges: g.querySelector('[data-id="edges"]'), layer: make("g", {}, g)};
      var dots = g.querySelector('[data-id="vertices"]');
      Array.prototype.forEach.call(dots ? dots.children : [], function (dot, v) {
        var title = dot.querySelector("title"), text = title ? title.textContent : "v" + v;
        p.at.push([dot.getAttribute("cx"), dot.getAttribute("cy")]);
        var hit = make("circle", {cx: p.at[v][0], cy: p.at[v][1], r: 8, "class": "hit", tabindex: 0,
                                  "data-vertex": v, "aria-label": text}, g);
        function on() {
          var r = hit.getBoundingClientRect();
          tip.textContent = text;
          tip.style.left = (r.left + r.width / 2 + scrollX) + "px";
          tip.style.top = (r.top + scrollY) + "px";
          tip.hidden = false;
          ring(v);
        }
        function off() { tip.hidden = true; ring(-1); }
        hit.addEventListener("mouseenter", on); hit.addEventListener("focus", on);
        hit.addEventListener("mouseleave", off); hit.addEventListener("blur", off);
        if (title) title.remove();  // the tooltip above says it at once
      });
      return p;
    }).filter(Boolean);
    function clear(cls) {
      panels.forEach(function (p) { p.layer.querySelectorAll("." + cls).forEach(function (x) { x.remove(); }); });
    }
    function ring(v) {
      clear("ring");
      panels.forEach(function (p) { if (p.at[v]) make("circle", {cx: p.at[v][0], cy: p.at[v][1], r: 9, "class": "ring"}, p.layer); });
    }
    // A walk along the edges as drawn (bent ones too); a step that is no edge straight.
    function draw(walk, closed, ink) {
      panels.forEach(function (p) {
        for (var i = 0; i < (closed ? walk.length : walk.length - 1); ++i) {
          var u = walk[i], v = walk[(i + 1) % walk.length], m = edge.get(u + " " + v), d;
          if (m && p.edges && p.edges.children[m.e]) {
            var pts = p.edges.children[m.e].getAttribute("d").match(/-?[0-9.]+/g), xy = [];
            for (var k = 0; k + 1 < pts.length; k += 2) xy.push(pts[k] + " " + pts[k + 1]);
            if (m.back) xy.reverse();
            d = "M" + xy.join("L");
          } else if (p.at[u] && p.at[v]) {
            d = "M" + p.at[u].join(" ") + "L" + p.at[v].join(" ");
          } else continue;
          make("path", {d: d, "class": "hl " + ink + (m ? "" : " jump")}, p.layer);
        }
      });
    }
    var pinned = null;
    function show(item) {
      clear("hl");
      if (!item) return;
      draw(ids(item.getAttribute("data-walk")), item.hasAttribute("data-closed"), item.getAttribute("data-ink"));
      if (item.hasAttribute("data-walk2")) draw(ids(item.getAttribute("data-walk2")), false, "reference");
    }
    section.querySelectorAll(".walk").forEach(function (item) {
      item.addEventListener("mouseenter", function () { show(item); });
      item.addEventListener("focus", function () { show(item); });
      item.addEventListener("mouseleave", function () { show(pinned); });
      item.addEventListener("blur", function () { show(pinned); });
      item.addEventListener("click", function () {
        if (pinned) pinned.classList.remove("pinned");
        pinned = pinned === item ? null : item;
        if (pinned) pinned.classList.add("pinned");
        show(pinned);
      });
    });
  }
  document.querySelectorAll("section.failure").forEach(setUp);
  if (location.hash === "#selftest") {
    var first = document.querySelector("section.failure");
    if (first) {
      var item = first.querySelector(".differences .walk") || first.querySelector(".walk");
      if (item) item.click();
      var hit = first.querySelector('[data-id="answer"] .hit') || first.querySelector(".hit");
      if (hit) hit.dispatchEvent(new MouseEvent("mouseenter"));
    }
    document.body.setAttribute("data-selftest", "done");
  }
})();
)JS";
}

}  // namespace dcel::diff
