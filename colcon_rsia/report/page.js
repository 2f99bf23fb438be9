// The report page's behaviour: the graph view (pan, zoom, fit, search,
// evidence panel, collapsible clusters, impact focus), the table filter and
// sortable columns. Inline in index.html; it loads nothing.
(function () {
  'use strict';
  function all(selector, root) {
    return Array.prototype.slice.call(
      (root || document).querySelectorAll(selector));
  }
  function element(tag, text, className) {
    var made = document.createElement(tag);
    if (text !== undefined && text !== null) { made.textContent = text; }
    if (className) { made.className = className; }
    return made;
  }

  // --- the graph view ------------------------------------------------------
  var svg = document.getElementById('graph');
  var view = document.getElementById('graph-view');
  var box = document.getElementById('graph-box');
  var panel = document.getElementById('graph-panel');
  var data = JSON.parse(document.getElementById('graph-data').textContent);
  var vertices = all('g.vertex', svg);
  var edges = all('path.edge', svg);
  var byKey = {};
  vertices.forEach(function (v) { byKey[v.getAttribute('data-key')] = v; });
  var transform = { x: 0, y: 0, k: 1 };
  var MIN_SCALE = 0.02;
  var MAX_SCALE = 4;

  function show() {
    view.setAttribute('transform', 'translate(' + transform.x.toFixed(2) +
      ',' + transform.y.toFixed(2) + ') scale(' + transform.k.toFixed(4) + ')');
    svg.setAttribute('data-scale', transform.k.toFixed(4));
  }
  function viewSize() {
    var rect = svg.getBoundingClientRect();
    return { width: rect.width || 800, height: rect.height || 600 };
  }
  // show the drawing rectangle [x0, x1] x [y0, y1] in the middle, with the
  // scale between lowest and highest
  function frame(x0, y0, x1, y1, lowest, highest) {
    var size = viewSize();
    var pad = 24;
    var k = Math.min((size.width - 2 * pad) / Math.max(1, x1 - x0),
      (size.height - 2 * pad) / Math.max(1, y1 - y0));
    k = Math.max(lowest, Math.min(highest, k));
    transform.k = k;
    transform.x = size.width / 2 - k * (x0 + x1) / 2;
    transform.y = size.height / 2 - k * (y0 + y1) / 2;
    show();
  }
  function bounds(elements) {
    var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    elements.forEach(function (e) {
      var b = e.getBBox();
      x0 = Math.min(x0, b.x); y0 = Math.min(y0, b.y);
      x1 = Math.max(x1, b.x + b.width); y1 = Math.max(y1, b.y + b.height);
    });
    return [x0, y0, x1, y1];
  }
  function fitAll() {
    frame(0, 0, Number(svg.getAttribute('data-width')),
      Number(svg.getAttribute('data-height')), MIN_SCALE, 1.2);
  }
  function zoomAt(factor, cx, cy) {
    var k = Math.max(MIN_SCALE, Math.min(MAX_SCALE, transform.k * factor));
    transform.x = cx - (cx - transform.x) * k / transform.k;
    transform.y = cy - (cy - transform.y) * k / transform.k;
    transform.k = k;
    show();
  }
  function zoomCentre(factor) {
    var size = viewSize();
    zoomAt(factor, size.width / 2, size.height / 2);
  }
  function centreOn(target) {
    var b = bounds([target]);
    var size = viewSize();
    var k = Math.max(transform.k, 0.8);
    transform.k = k;
    transform.x = size.width / 2 - k * (b[0] + b[2]) / 2;
    transform.y = size.height / 2 - k * (b[1] + b[3]) / 2;
    show();
  }
  // the first view: readable, centred on the changed nodes and what they
  // reach, with the changed nodes in it; without changes the whole graph
  var READABLE = 0.5;
  function initialView() {
    var changed = all('g.vertex.changed', svg);
    var size = viewSize();
    var whole = Math.min(
      size.width / Number(svg.getAttribute('data-width')),
      size.height / Number(svg.getAttribute('data-height')));
    if (!changed.length || whole >= 0.6) { fitAll(); return; }
    var b = bounds(changed.concat(all('g.vertex.rate', svg),
      all('g.vertex.topic.stopped', svg)));
    frame(b[0], b[1], b[2], b[3], READABLE, 1.2);
    // move as little as needed to bring the changed nodes into the view
    var c = bounds(changed);
    var pad = 24;
    var k = transform.k;
    var left = transform.x + k * c[0], right = transform.x + k * c[2];
    var top = transform.y + k * c[1], bottom = transform.y + k * c[3];
    if (right - left > size.width - 2 * pad ||
        bottom - top > size.height - 2 * pad) {
      frame(c[0], c[1], c[2], c[3], READABLE, 1.0);
      return;
    }
    if (left < pad) { transform.x += pad - left; }
    if (right > size.width - pad) { transform.x -= right - size.width + pad; }
    if (top < pad) { transform.y += pad - top; }
    if (bottom > size.height - pad) {
      transform.y -= bottom - size.height + pad;
    }
    show();
  }

  box.addEventListener('wheel', function (event) {
    event.preventDefault();
    var rect = svg.getBoundingClientRect();
    zoomAt(Math.exp(-event.deltaY * 0.0015), event.clientX - rect.left,
      event.clientY - rect.top);
  }, { passive: false });
  var drag = null;
  box.addEventListener('pointerdown', function (event) {
    if (event.button !== 0) { return; }
    drag = { x: event.clientX, y: event.clientY, moved: false,
      tx: transform.x, ty: transform.y };
  });
  window.addEventListener('pointermove', function (event) {
    if (!drag) { return; }
    var dx = event.clientX - drag.x, dy = event.clientY - drag.y;
    if (!drag.moved && Math.abs(dx) + Math.abs(dy) < 4) { return; }
    drag.moved = true;
    box.classList.add('dragging');
    transform.x = drag.tx + dx;
    transform.y = drag.ty + dy;
    show();
  });
  window.addEventListener('pointerup', function () {
    if (drag && drag.moved) {
      // the click that ends a drag selects nothing
      svg.setAttribute('data-dragged', 'true');
    }
    drag = null;
    box.classList.remove('dragging');
  });

  function button(id, action) {
    document.getElementById(id).addEventListener('click', action);
  }
  button('zoom-in', function () { zoomCentre(1.4); });
  button('zoom-out', function () { zoomCentre(1 / 1.4); });
  button('zoom-fit', fitAll);
  var focus = document.getElementById('focus-impact');
  if (focus) {
    focus.addEventListener('click', function () {
      var on = !svg.classList.contains('focus');
      svg.classList.toggle('focus', on);
      focus.setAttribute('aria-pressed', String(on));
    });
  }

  // clusters: a click on the name hides or shows what is inside
  var clusters = all('g.cluster', svg);
  function collapse(cluster, collapsed) {
    var key = cluster.getAttribute('data-cluster');
    cluster.classList.toggle('collapsed', collapsed);
    var inside = {};
    vertices.forEach(function (v) {
      if (v.getAttribute('data-cluster') === key) {
        inside[v.getAttribute('data-key')] = true;
        v.classList.toggle('hidden', collapsed);
      }
    });
    edges.forEach(function (e) {
      var source = inside[e.getAttribute('data-source')];
      var target = inside[e.getAttribute('data-target')];
      if (source && target) { e.classList.toggle('hidden', collapsed); }
    });
  }
  clusters.forEach(function (cluster) {
    cluster.querySelector('text').addEventListener('click', function () {
      collapse(cluster, !cluster.classList.contains('collapsed'));
    });
  });
  var collapseAll = document.getElementById('collapse-all');
  if (collapseAll) {
    collapseAll.addEventListener('click', function () {
      var collapsed = collapseAll.getAttribute('aria-pressed') !== 'true';
      clusters.forEach(function (c) { collapse(c, collapsed); });
      collapseAll.setAttribute('aria-pressed', String(collapsed));
    });
  }

  // search: every match outlined, the first (then the next) centred
  var search = document.getElementById('graph-search');
  var found = document.getElementById('graph-found');
  var matches = [];
  var current = -1;
  function find() {
    var text = search.value.trim().toLowerCase();
    matches = [];
    vertices.forEach(function (v) {
      var hit = text.length > 0 &&
        v.getAttribute('data-name').toLowerCase().indexOf(text) >= 0;
      v.classList.toggle('match', hit);
      if (hit) { matches.push(v); }
    });
    // the exact name first, then the nodes, then the topics
    matches.sort(function (a, b) {
      function rank(v) {
        return (v.getAttribute('data-name').toLowerCase() === text ? 0 : 2) +
          (v.classList.contains('node') ? 0 : 1);
      }
      return rank(a) - rank(b);
    });
    current = -1;
    next();
  }
  function next() {
    if (!matches.length) {
      found.textContent = search.value.trim() ? 'not found' : '';
      return;
    }
    current = (current + 1) % matches.length;
    var target = matches[current];
    var cluster = target.getAttribute('data-cluster');
    if (cluster && target.classList.contains('hidden')) {
      collapse(svg.querySelector('g.cluster[data-cluster="' + cluster + '"]'),
        false);
    }
    centreOn(target);
    found.textContent = (current + 1) + ' of ' + matches.length;
    svg.setAttribute('data-found', target.getAttribute('data-name'));
  }
  search.addEventListener('input', find);
  search.addEventListener('keydown', function (event) {
    if (event.key === 'Enter') { event.preventDefault(); next(); }
  });

  // the evidence panel
  var STATUS = { changed: 'changed', rate: 'in the rate-aware impact set',
    traditional: 'in the traditional impact set only',
    '': 'not impacted' };
  function heading(text) { panel.appendChild(element('h3', text)); }
  function line(text, className) {
    panel.appendChild(element('p', text, className));
  }
  function list(items) {
    var ul = element('ul');
    items.forEach(function (item) { ul.appendChild(item); });
    panel.appendChild(ul);
    return ul;
  }
  function publisherItem(p) {
    // [topic, label, pattern, rate, location, [[kind, location, detail]]]
    var li = element('li');
    li.appendChild(element('code', p[0]));
    li.appendChild(document.createTextNode(' '));
    li.appendChild(element('span', p[1], 'label-' + p[1]));
    li.appendChild(document.createTextNode(
      ' (' + p[2] + (p[3] ? ', ' + p[3] + ' Hz' : '') + ') at '));
    li.appendChild(element('code', p[4]));
    if (p[5].length) {
      var ul = element('ul');
      p[5].forEach(function (e) {
        var item = element('li');
        item.appendChild(element('code', e[1]));
        item.appendChild(document.createTextNode(
          ' ' + e[0] + (e[2] ? ': ' + e[2] : '')));
        ul.appendChild(item);
      });
      li.appendChild(ul);
    }
    return li;
  }
  function subscriberItem(s) {
    // [topic, location, callback]
    var li = element('li');
    li.appendChild(element('code', s[0]));
    li.appendChild(document.createTextNode(' at '));
    li.appendChild(element('code', s[1]));
    if (s[2]) { li.appendChild(document.createTextNode(' → ' + s[2])); }
    return li;
  }
  function nameItem(name, suffix) {
    var li = element('li');
    li.appendChild(element('code', name));
    if (suffix) { li.appendChild(document.createTextNode(' ' + suffix)); }
    return li;
  }
  function showNode(id) {
    var node = data.nodes[id];
    heading(id);
    line(node.exe + ' · ' + node.fqn, 'muted');
    line(STATUS[node.status] + (node.why ? ': ' + node.why : ''));
    panel.appendChild(element('strong', 'publishes'));
    if (node.pub.length) {
      list(node.pub.map(publisherItem));
    } else {
      line(node.analysed ? 'nothing' : 'not analysed', 'muted');
    }
    panel.appendChild(element('strong', 'subscribes'));
    if (node.sub.length) {
      list(node.sub.map(subscriberItem));
    } else { line('nothing', 'muted'); }
  }
  function showTopic(name, copies) {
    var topic = data.topics[name];
    heading(name);
    if (copies > 1) {
      line('a hub topic: drawn once in each of the ' + copies +
        ' clusters it connects', 'muted');
    }
    panel.appendChild(element('strong', 'publishers'));
    list(topic.pub.map(function (p) { return nameItem(p[0], p[1]); }));
    panel.appendChild(element('strong', 'subscribers'));
    list(topic.sub.map(function (s) { return nameItem(s); }));
  }
  function showEdge(edge) {
    var source = byKey[edge.getAttribute('data-source')];
    var target = byKey[edge.getAttribute('data-target')];
    var fromNode = source.classList.contains('node');
    var node = (fromNode ? source : target).getAttribute('data-name');
    var topic = (fromNode ? target : source).getAttribute('data-name');
    heading(node + (fromNode ? ' publishes ' : ' subscribes ') + topic);
    if (edge.classList.contains('crossed')) {
      line('The rate change goes through this edge.');
    } else if (edge.classList.contains('stopped')) {
      line('The rate change stops here: the publisher keeps its own rate.');
    }
    var entries = fromNode ? data.nodes[node].pub : data.nodes[node].sub;
    list(entries.filter(function (e) { return e[0] === topic; })
      .map(fromNode ? publisherItem : subscriberItem));
  }
  function select(target) {
    all('.selected', svg).forEach(function (e) {
      e.classList.remove('selected');
    });
    panel.textContent = '';
    target.classList.add('selected');
    if (target.classList.contains('edge')) {
      showEdge(target);
    } else if (target.classList.contains('node')) {
      showNode(target.getAttribute('data-name'));
    } else {
      showTopic(target.getAttribute('data-name'),
        Number(target.getAttribute('data-copies') || 1));
    }
    svg.setAttribute('data-selected', target.getAttribute('data-name') ||
      target.getAttribute('data-key'));
  }
  svg.addEventListener('click', function (event) {
    if (svg.getAttribute('data-dragged') === 'true') {
      svg.removeAttribute('data-dragged');
      return;
    }
    var target = event.target.closest('g.vertex, path.edge');
    if (target) { select(target); }
  });

  // --- the tables: filter and sort ------------------------------------------
  var input = document.getElementById('filter');
  var count = document.getElementById('filter-count');
  var rows = all('tr[data-filter]');
  var tables = all('table[data-filterable]');
  var texts = rows.map(function (row) {
    return row.textContent.toLowerCase();
  });
  function matchesAll(text, words) {
    return words.every(function (word) { return text.indexOf(word) >= 0; });
  }
  function filter() {
    var words = input.value.trim().toLowerCase().split(/\s+/)
      .filter(function (word) { return word.length > 0; });
    var shown = 0;
    rows.forEach(function (row, index) {
      var match = matchesAll(texts[index], words);
      row.hidden = !match;
      if (match) { shown += 1; }
    });
    vertices.forEach(function (vertex) {
      var name = vertex.getAttribute('data-name').toLowerCase();
      vertex.classList.toggle(
        'dimmed', words.length > 0 && !matchesAll(name, words));
    });
    tables.forEach(function (table) {
      table.setAttribute('data-shown', String(
        table.querySelectorAll('tr[data-filter]:not([hidden])').length));
    });
    count.textContent = shown + ' of ' + rows.length + ' rows';
    document.body.setAttribute('data-shown-rows', String(shown));
  }
  input.addEventListener('input', filter);
  // '#filter=words' in the address fills the box
  var preset = /^#filter=(.*)$/.exec(window.location.hash);
  if (preset) {
    try {
      input.value = decodeURIComponent(preset[1]);
    } catch (e) {
      // a '%' that escapes nothing ('#filter=100%'): the text as written
      input.value = preset[1];
    }
  }

  function sortKey(cell) {
    var value = cell.hasAttribute('data-sort') ?
      cell.getAttribute('data-sort') : cell.textContent.trim().toLowerCase();
    var number = Number(value);
    return value !== '' && !isNaN(number) ? number : value;
  }
  all('table.sortable').forEach(function (table) {
    var headers = all('thead th', table);
    var body = table.tBodies[0];
    headers.forEach(function (th, column) {
      th.setAttribute('title', 'sort');
      th.addEventListener('click', function () {
        var ascending = th.getAttribute('aria-sort') !== 'ascending';
        headers.forEach(function (h) { h.removeAttribute('aria-sort'); });
        th.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
        var keyed = Array.prototype.map.call(body.rows, function (row, i) {
          var cell = row.cells[column];
          return { row: row, key: cell ? sortKey(cell) : '', index: i };
        });
        keyed.sort(function (a, b) {
          var order = 0;
          if (typeof a.key === typeof b.key) {
            order = a.key < b.key ? -1 : a.key > b.key ? 1 : 0;
          } else {
            order = typeof a.key === 'number' ? -1 : 1;
          }
          return (ascending ? order : -order) || a.index - b.index;
        });
        keyed.forEach(function (k) { body.appendChild(k.row); });
      });
    });
  });

  show();
  initialView();
  filter();
  document.body.setAttribute('data-rows', String(rows.length));
  document.body.setAttribute('data-rendered', 'true');
})();
