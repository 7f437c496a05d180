// Tessera's 360-degree panorama viewer: an equirectangular image shown as the view from inside
// a sphere. No library and no network: WebGL when the browser has it, otherwise the same
// projection computed per pixel on a 2D canvas. The image comes as a data: URI from
// panorama.js (window.TESSERA_PANORAMA), because browsers refuse to let WebGL read images
// loaded from file:// addresses.
(function () {
  "use strict";
  var canvas = document.getElementById("pano");
  var status = document.getElementById("pano-status");
  var view = { yaw: 0, pitch: 0, fov: 75 }; // degrees; yaw 0 = the panorama's centre
  var draw = null;

  function clamp(v, lo, hi) { return v < lo ? lo : v > hi ? hi : v; }

  // The view direction of canvas pixel (x, y), as longitude and latitude in radians.
  function ray(x, y, w, h, out) {
    var f = 1 / Math.tan(view.fov * Math.PI / 360);
    var u = (2 * (x + 0.5) / w - 1) * (w / h), v = 1 - 2 * (y + 0.5) / h;
    var cy = Math.cos(view.yaw * Math.PI / 180), sy = Math.sin(view.yaw * Math.PI / 180);
    var cp = Math.cos(view.pitch * Math.PI / 180), sp = Math.sin(view.pitch * Math.PI / 180);
    // camera space (u right, v up, f forward) to world (x east, y north, z up)
    var dx = u, dy = f * cp - v * sp, dz = f * sp + v * cp;
    var rx = dx * cy + dy * sy, ry = -dx * sy + dy * cy;
    out[0] = Math.atan2(rx, ry);
    out[1] = Math.atan2(dz, Math.sqrt(rx * rx + ry * ry));
  }

  function webgl(img) {
    var gl = canvas.getContext("webgl");
    if (!gl) return null;
    var vs = "attribute vec2 p; varying vec2 q; void main() { q = p; gl_Position = vec4(p, 0., 1.); }";
    var fs = [
      "precision highp float; varying vec2 q; uniform sampler2D img;",
      "uniform float yaw, pitch, f, aspect;",
      "void main() {",
      "  vec3 d = vec3(q.x * aspect, f * cos(pitch) - q.y * sin(pitch), f * sin(pitch) + q.y * cos(pitch));",
      "  vec2 r = vec2(d.x * cos(yaw) + d.y * sin(yaw), -d.x * sin(yaw) + d.y * cos(yaw));",
      "  float lon = atan(r.x, r.y), lat = atan(d.z, length(r));",
      "  gl_FragColor = texture2D(img, vec2(lon / 6.2831853 + 0.5, 0.5 - lat / 3.1415927));",
      "}"].join("\n");
    function shader(type, src) {
      var s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      return gl.getShaderParameter(s, gl.COMPILE_STATUS) ? s : null;
    }
    var prog = gl.createProgram(), v = shader(gl.VERTEX_SHADER, vs), fr = shader(gl.FRAGMENT_SHADER, fs);
    if (!v || !fr) return null;
    gl.attachShader(prog, v);
    gl.attachShader(prog, fr);
    gl.linkProgram(prog);
    if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) return null;
    gl.useProgram(prog);
    var buf = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    var loc = gl.getAttribLocation(prog, "p");
    gl.enableVertexAttribArray(loc);
    gl.vertexAttribPointer(loc, 2, gl.FLOAT, false, 0, 0);
    var tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    // Non-power-of-two images: no mipmaps, clamp in t, the seam is handled by the shader's
    // longitude (u wraps through 0.5 +- 0.5 exactly at the image edges).
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    try {
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA, gl.RGBA, gl.UNSIGNED_BYTE, img);
    } catch (e) {
      return null;
    }
    var u = {};
    ["yaw", "pitch", "f", "aspect"].forEach(function (n) { u[n] = gl.getUniformLocation(prog, n); });
    return function () {
      gl.viewport(0, 0, canvas.width, canvas.height);
      gl.uniform1f(u.yaw, view.yaw * Math.PI / 180);
      gl.uniform1f(u.pitch, view.pitch * Math.PI / 180);
      gl.uniform1f(u.f, 1 / Math.tan(view.fov * Math.PI / 360));
      gl.uniform1f(u.aspect, canvas.width / canvas.height);
      gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
    };
  }

  function software(img) {
    var src = document.createElement("canvas");
    src.width = img.width;
    src.height = img.height;
    var sctx = src.getContext("2d");
    sctx.drawImage(img, 0, 0);
    var pixels = sctx.getImageData(0, 0, img.width, img.height).data;
    var ctx = canvas.getContext("2d");
    return function () {
      var w = canvas.width, h = canvas.height, out = ctx.createImageData(w, h), r = [0, 0];
      for (var y = 0; y < h; y++) {
        for (var x = 0; x < w; x++) {
          ray(x, y, w, h, r);
          var sx = Math.min(img.width - 1, Math.floor((r[0] / (2 * Math.PI) + 0.5) * img.width));
          var sy = Math.min(img.height - 1, Math.floor((0.5 - r[1] / Math.PI) * img.height));
          var i = 4 * (sy * img.width + sx), o = 4 * (y * w + x);
          out.data[o] = pixels[i];
          out.data[o + 1] = pixels[i + 1];
          out.data[o + 2] = pixels[i + 2];
          out.data[o + 3] = 255;
        }
      }
      ctx.putImageData(out, 0, 0);
    };
  }

  var pending = false;
  function redraw() {
    if (!draw || pending) return;
    pending = true;
    requestAnimationFrame(function () { pending = false; draw(); });
  }

  var drag = null;
  canvas.addEventListener("mousedown", function (e) { drag = [e.clientX, e.clientY]; });
  window.addEventListener("mouseup", function () { drag = null; });
  window.addEventListener("mousemove", function (e) {
    if (!drag) return;
    var k = view.fov / canvas.height;
    view.yaw -= (e.clientX - drag[0]) * k;
    view.pitch = clamp(view.pitch + (e.clientY - drag[1]) * k, -89, 89);
    drag = [e.clientX, e.clientY];
    redraw();
  });
  canvas.addEventListener("wheel", function (e) {
    view.fov = clamp(view.fov + (e.deltaY > 0 ? 5 : -5), 30, 110);
    e.preventDefault();
    redraw();
  }, { passive: false });

  if (!window.TESSERA_PANORAMA) {
    status.textContent = "No panorama in this export.";
    return;
  }
  var img = new Image();
  img.onload = function () {
    draw = webgl(img);
    var how = "WebGL";
    if (!draw) {
      draw = software(img);
      how = "canvas";
    }
    draw();
    status.textContent = "Drag to look around, scroll to zoom (" + how + ").";
    document.body.setAttribute("data-pano", "ready");
  };
  img.onerror = function () { status.textContent = "The panorama image could not be read."; };
  img.src = window.TESSERA_PANORAMA;
})();
