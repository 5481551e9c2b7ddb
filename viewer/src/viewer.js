// cambrian's trajectory viewer: one panel per creature (three.js), a shared timeline with
// play / pause / scrub / speed, orbit or follow camera, the phase and the fitness shown. The data
// come from analysis/view.py, embedded in the page as JSON (<script id="cambrian-data">); the
// page's state is mirrored as JSON in <pre id="cambrian-status"> for tests.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

// part colours by depth in the body tree (root first), held objects red, the light yellow
const PART_COLOURS = [0x4878d0, 0xee854a, 0x6acc64, 0x956cb4, 0x8c613c, 0xdc7ec0, 0x82c6e2];
const HELD_COLOUR = 0xd62728;
const LIGHT_COLOUR = 0xffd700;
const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 4];

// the index of the last frame whose time is <= t (binary search; 0 before the first)
function frameAt(times, t) {
  let lo = 0;
  let hi = times.length - 1;
  if (hi < 0 || t <= times[0]) return 0;
  if (t >= times[hi]) return hi;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid;
    else hi = mid;
  }
  return lo;
}

// the ground's z at (x, y): 0, or on a terrain's triangles as the physics makes them (each grid
// square split from (c + 1, r) to (c, r + 1)); outside the terrain, its edge's
function groundHeight(terrain, x, y) {
  if (!terrain) return 0;
  const n = terrain.samples, h = terrain.heights, half = (n - 1) / 2;
  const gx = Math.min(Math.max(x / terrain.spacing + half, 0), n - 1);
  const gy = Math.min(Math.max(y / terrain.spacing + half, 0), n - 1);
  const c = Math.min(Math.floor(gx), n - 2), r = Math.min(Math.floor(gy), n - 2);
  const u = gx - c, v = gy - r;
  const at = (dc, dr) => h[(r + dr) * n + c + dc];
  if (u + v <= 1) return at(0, 0) + u * (at(1, 0) - at(0, 0)) + v * (at(0, 1) - at(0, 0));
  return at(1, 1) + (1 - u) * (at(0, 1) - at(1, 1)) + (1 - v) * (at(1, 0) - at(1, 1));
}

// a heightfield terrain as the physics triangulates it, with a 1 m grid on it
function terrainMesh(terrain) {
  const n = terrain.samples, spacing = terrain.spacing, half = (n - 1) / 2;
  const positions = new Float32Array(n * n * 3);
  const uvs = new Float32Array(n * n * 2);
  const colours = new Float32Array(n * n * 3);
  const low = Math.min(...terrain.heights), high = Math.max(...terrain.heights);
  const valley = new THREE.Color(0x6f8f5a), top = new THREE.Color(0xe8e2c4), tint = new THREE.Color();
  for (let r = 0; r < n; r++) {
    for (let c = 0; c < n; c++) {
      const i = r * n + c, x = (c - half) * spacing, y = (r - half) * spacing;
      positions.set([x, y, terrain.heights[i]], 3 * i);
      uvs.set([x, y], 2 * i);  // metres: the texture's cell repeats every metre
      // valleys darker, tops lighter: the hills read at a glance
      tint.copy(valley).lerp(top, high > low ? (terrain.heights[i] - low) / (high - low) : 0.5);
      colours.set([tint.r, tint.g, tint.b], 3 * i);
    }
  }
  const index = [];
  for (let r = 0; r + 1 < n; r++) {
    for (let c = 0; c + 1 < n; c++) {
      const a = r * n + c, b = a + 1, d = a + n, e = d + 1;
      index.push(a, b, d, b, e, d);  // counter-clockwise seen from above
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute("uv", new THREE.BufferAttribute(uvs, 2));
  geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  const mesh = new THREE.Mesh(
    geometry,
    new THREE.MeshStandardMaterial({
      map: gridTexture("#ffffff", "#9aa39a", 1),
      vertexColors: true,
      roughness: 1,
    })
  );
  mesh.receiveShadow = true;
  return mesh;
}

// a texture of one 1 m grid cell (`fill` with `line` edges), repeated over a `size` m plane
function gridTexture(fill, line, size) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const context = canvas.getContext("2d");
  context.fillStyle = fill;
  context.fillRect(0, 0, 64, 64);
  context.fillStyle = line;
  context.fillRect(0, 0, 64, 2);
  context.fillRect(0, 0, 2, 64);
  const texture = new THREE.CanvasTexture(canvas);
  texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
  texture.repeat.set(size, size);
  texture.anisotropy = 8;
  texture.colorSpace = THREE.SRGBColorSpace;
  return texture;
}

// the geometry of a part or object: `h` half its size as PartShape reads it (a capsule or
// cylinder lies along x, h[0] half its length and h[1] its radius; a sphere's radius is h[0])
function shapeGeometry(shape, h) {
  if (shape === "sphere") return new THREE.SphereGeometry(h[0], 24, 16);
  if (shape === "capsule" || shape === "cylinder") {
    const geometry = shape === "capsule"
      ? new THREE.CapsuleGeometry(h[1], Math.max(0, 2 * h[0] - 2 * h[1]), 8, 20)
      : new THREE.CylinderGeometry(h[1], h[1], 2 * h[0], 24);
    geometry.rotateZ(-Math.PI / 2);  // three.js builds them along y; ours lie along x
    return geometry;
  }
  return new THREE.BoxGeometry(2 * h[0], 2 * h[1], 2 * h[2]);
}

// depth of every part in the body tree (parents precede children)
function depths(parents) {
  const depth = [];
  parents.forEach((parent, i) => {
    depth[i] = parent < 0 ? 0 : depth[parent] + 1;
  });
  return depth;
}

function element(tag, attributes = {}, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text) node.textContent = text;
  return node;
}

// one creature: its three.js scene, camera, controls and the meshes it moves frame by frame
class Panel {
  constructor(data, container, index) {
    this.data = data;
    this.parts = data.parts.half_extents.length;
    this.held = data.held ? data.held.half_extents.length : 0;
    this.frames = data.time.length;
    this.frame = 0;
    this.index = index;

    this.root = element("div", { class: "panel", "data-index": String(index) });
    this.canvas = element("canvas");
    this.caption = element("div", { class: "caption" });
    this.clock = element("div", { class: "clock" });
    this.root.append(this.canvas, this.caption, this.clock);
    container.append(this.root);
    this.caption.textContent = this.describe();

    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.shadowMap.enabled = true;
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(45, 1, 0.05, 2000);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = false;
    this.build();
  }

  // "gen 10 · id 4242 · walk · fitness 12.3 (ok)"
  describe() {
    const d = this.data;
    const bits = [];
    if (d.label) bits.push(d.label);
    if (d.creature_id !== null && d.creature_id !== undefined) bits.push(`id ${d.creature_id}`);
    bits.push(d.task || "task ?");
    bits.push(`fitness ${Number(d.fitness).toPrecision(4)} (${d.status})`);
    return bits.join(" · ");
  }

  build() {
    const d = this.data;
    const water = d.ground === "none";
    this.scene.background = new THREE.Color(water ? 0x1d4e89 : 0xdfe8f0);
    if (water) this.scene.fog = new THREE.Fog(0x1d4e89, 5, 60);

    // light: sky and sun (shadows), following the creature
    this.scene.add(new THREE.HemisphereLight(0xffffff, water ? 0x0b2545 : 0x8d8d8d, 1.6));
    this.sun = new THREE.DirectionalLight(0xffffff, 2.2);
    this.sun.castShadow = true;
    this.sun.shadow.mapSize.set(1024, 1024);
    const reach = 6;
    Object.assign(this.sun.shadow.camera, { left: -reach, right: reach, top: reach, bottom: -reach });
    this.scene.add(this.sun, this.sun.target);

    // the ground: a plane with a 1 m grid drawn into its texture; in water no ground, the same
    // grid, faint, 2 m under the start for depth
    const extent = this.extent();
    const size = 2 * Math.max(20, Math.ceil(extent + 10));
    const ground = new THREE.Mesh(
      new THREE.PlaneGeometry(size, size),
      new THREE.MeshStandardMaterial({
        map: gridTexture(water ? "#1d4e89" : "#c8d2c0", water ? "#5b8ac4" : "#8f9a8c", size),
        roughness: 1,
        transparent: water,
        opacity: water ? 0.35 : 1,
      })
    );
    ground.position.set(Math.round(d.com[0]), Math.round(d.com[1]), water ? d.com[2] - 2 : 0);
    ground.receiveShadow = !water;
    this.scene.add(ground);
    // hills: their terrain, and the flat plane (where the physics has it) under its lowest point
    this.terrainMesh = null;
    if (d.terrain) {
      this.terrainMesh = terrainMesh(d.terrain);
      this.scene.add(this.terrainMesh);
      ground.position.z = Math.min(...d.terrain.heights);
    }

    // the body: one box per part, coloured by its depth in the tree
    const depth = depths(d.parts.parent);
    this.partMeshes = d.parts.half_extents.map((h, i) => {
      const shape = (d.parts.shape || [])[i] || "box";
      const mesh = new THREE.Mesh(
        shapeGeometry(shape, h),
        new THREE.MeshStandardMaterial({
          color: PART_COLOURS[depth[i] % PART_COLOURS.length],
          roughness: 0.6,
        })
      );
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      mesh.add(new THREE.LineSegments(
        new THREE.EdgesGeometry(mesh.geometry, 30),
        new THREE.LineBasicMaterial({ color: 0x1a1a1a })
      ));
      // a part without a shape of its own (a springy organism's proxy) is a mass, not drawn
      mesh.visible = !d.parts.solid || d.parts.solid[i] !== false;
      this.scene.add(mesh);
      return mesh;
    });
    // shapes the parts carry (a springy organism's tubes), fixed in their part's frame
    this.colliderMeshes = [];
    const carried = d.colliders;
    for (let k = 0; carried && k < carried.part.length; k++) {
      const mesh = new THREE.Mesh(
        shapeGeometry(carried.shape[k] || "box", carried.half_extents[k]),
        this.partMeshes[carried.part[k]].material
      );
      mesh.position.set(carried.position[3 * k], carried.position[3 * k + 1], carried.position[3 * k + 2]);
      mesh.quaternion.set(carried.orientation[4 * k], carried.orientation[4 * k + 1],
        carried.orientation[4 * k + 2], carried.orientation[4 * k + 3]);
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      // in a holder that follows the part, so it shows even where the part itself is not drawn
      const holder = new THREE.Object3D();
      holder.add(mesh);
      this.scene.add(holder);
      this.colliderMeshes.push({ holder, mesh, part: carried.part[k] });
    }
    // held objects (a catapult's projectile)
    this.heldMeshes = [];
    for (let k = 0; k < this.held; k++) {
      const h = d.held.half_extents[k];
      const mesh = new THREE.Mesh(
        shapeGeometry((d.held.shape || [])[k] || "box", h),
        new THREE.MeshStandardMaterial({ color: HELD_COLOUR, roughness: 0.5 })
      );
      mesh.castShadow = true;
      this.scene.add(mesh);
      this.heldMeshes.push(mesh);
    }
    // the light the photosensors point at
    if (d.light) {
      this.lightMesh = new THREE.Mesh(
        new THREE.SphereGeometry(0.15, 16, 12),
        new THREE.MeshBasicMaterial({ color: LIGHT_COLOUR })
      );
      this.scene.add(this.lightMesh);
    }
    // where the creature started, for scale
    const start = new THREE.Mesh(
      new THREE.RingGeometry(0.18, 0.22, 32),
      new THREE.MeshBasicMaterial({ color: 0x333333, side: THREE.DoubleSide })
    );
    start.position.set(d.com[0], d.com[1], water ? d.com[2] : groundHeight(d.terrain, d.com[0], d.com[1]) + 0.01);
    this.scene.add(start);

    // the camera: looking at the start from behind and above, at the body's size
    this.lastCom = new THREE.Vector3(d.com[0], d.com[1], d.com[2]);
    const span = Math.max(1.5, this.bodySize() * 4);
    this.controls.target.copy(this.lastCom);
    this.camera.position.set(this.lastCom.x - span, this.lastCom.y - span, this.lastCom.z + span * 0.7);
    this.controls.update();
  }

  // the largest distance of the centre of mass (or a held object) from where it started, m
  extent() {
    const d = this.data;
    let far = 0;
    const check = (x, y) => {
      far = Math.max(far, Math.hypot(x - d.com[0], y - d.com[1]));
    };
    for (let f = 0; f < this.frames; f++) check(d.com[3 * f], d.com[3 * f + 1]);
    if (this.held) {
      const p = d.held.position;
      for (let i = 0; i < p.length; i += 3) check(p[i], p[i + 1]);
    }
    return far;
  }

  // the body's largest part side, m
  bodySize() {
    let size = 0.1;
    for (const h of this.data.parts.half_extents) size = Math.max(size, 2 * Math.max(...h));
    return size * Math.sqrt(this.parts);
  }

  // shows frame f; `follow` moves the camera with the centre of mass
  show(f, follow) {
    const d = this.data;
    this.frame = f;
    for (let p = 0; p < this.parts; p++) {
      const i = f * this.parts + p;
      this.partMeshes[p].position.set(d.position[3 * i], d.position[3 * i + 1], d.position[3 * i + 2]);
      this.partMeshes[p].quaternion.set(
        d.orientation[4 * i], d.orientation[4 * i + 1], d.orientation[4 * i + 2], d.orientation[4 * i + 3]);
    }
    for (const { holder, part } of this.colliderMeshes) {
      holder.position.copy(this.partMeshes[part].position);
      holder.quaternion.copy(this.partMeshes[part].quaternion);
    }
    for (let k = 0; k < this.held; k++) {
      const i = f * this.held + k;
      const held = d.held;
      this.heldMeshes[k].position.set(held.position[3 * i], held.position[3 * i + 1], held.position[3 * i + 2]);
      this.heldMeshes[k].quaternion.set(
        held.orientation[4 * i], held.orientation[4 * i + 1], held.orientation[4 * i + 2], held.orientation[4 * i + 3]);
    }
    if (this.lightMesh) {
      this.lightMesh.position.set(d.light[3 * f], d.light[3 * f + 1], d.light[3 * f + 2]);
    }
    const com = new THREE.Vector3(d.com[3 * f], d.com[3 * f + 1], d.com[3 * f + 2]);
    if (follow) {
      const shift = com.clone().sub(this.lastCom);
      this.camera.position.add(shift);
      this.controls.target.add(shift);
    }
    this.lastCom.copy(com);
    this.sun.position.set(com.x + 4, com.y - 3, com.z + 8);
    this.sun.target.position.copy(com);
    const phase = d.phase_names[d.phase[f]] || "?";
    this.clock.textContent = `t ${d.time[f].toFixed(2)} s · ${phase} · frame ${f + 1}/${this.frames}`;
    this.clock.setAttribute("data-phase", phase);
  }

  render() {
    const width = this.canvas.clientWidth;
    const height = this.canvas.clientHeight;
    if (this.canvas.width !== Math.floor(width * this.renderer.getPixelRatio()) ||
        this.canvas.height !== Math.floor(height * this.renderer.getPixelRatio())) {
      this.renderer.setSize(width, height, false);
      this.camera.aspect = width / Math.max(height, 1);
      this.camera.updateProjectionMatrix();
    }
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }

  status() {
    return {
      label: this.data.label || "",
      parts: this.parts,
      meshes: this.partMeshes.length,
      shapes: this.partMeshes.map((m) => m.geometry.type),
      drawn_parts: this.partMeshes.filter((m) => m.visible).length,
      colliders: this.colliderMeshes.map(({ mesh }) => mesh.geometry.type),
      held: this.held,
      light: Boolean(this.lightMesh),
      ground: this.data.ground,
      terrain_vertices: this.terrainMesh ? this.terrainMesh.geometry.attributes.position.count : 0,
      frames: this.frames,
      frame: this.frame,
      phase: this.data.phase_names[this.data.phase[this.frame]],
    };
  }
}

// the page: panels, the timeline and its controls
class Viewer {
  constructor(scenes, title) {
    document.title = title;
    this.panels = [];
    this.playing = true;
    this.speed = 1;
    this.time = 0;
    this.rendered = 0;
    this.duration = Math.max(...scenes.map((s) => s.time[s.time.length - 1] || 0));

    const bar = element("div", { id: "bar" });
    this.playButton = element("button", { id: "play", type: "button" }, "pause");
    this.scrub = element("input", { id: "scrub", type: "range", min: "0", max: "1000", value: "0" });
    this.speedSelect = element("select", { id: "speed" });
    for (const s of SPEEDS) {
      const option = element("option", { value: String(s) }, `${s}×`);
      if (s === 1) option.selected = true;
      this.speedSelect.append(option);
    }
    this.cameraSelect = element("select", { id: "camera" });
    this.cameraSelect.append(element("option", { value: "follow" }, "follow"),
                             element("option", { value: "orbit" }, "orbit"));
    this.timeLabel = element("span", { id: "time" });
    bar.append(element("strong", {}, title), this.playButton, this.scrub, this.timeLabel,
               element("label", {}, "speed "), this.speedSelect,
               element("label", {}, "camera "), this.cameraSelect);
    const grid = element("div", { id: "panels" });
    grid.style.gridTemplateColumns = `repeat(${Math.min(scenes.length, 3)}, 1fr)`;
    this.statusNode = element("pre", { id: "cambrian-status", hidden: "" });
    document.body.append(bar, grid, this.statusNode);
    scenes.forEach((scene, i) => this.panels.push(new Panel(scene, grid, i)));

    this.playButton.addEventListener("click", () => this.setPlaying(!this.playing));
    this.scrub.addEventListener("input", () => {
      this.setPlaying(false);
      this.time = (Number(this.scrub.value) / 1000) * this.duration;
    });
    this.speedSelect.addEventListener("change", () => {
      this.speed = Number(this.speedSelect.value);
    });
    document.addEventListener("keydown", (event) => {
      if (event.code === "Space") {
        event.preventDefault();
        this.setPlaying(!this.playing);
      }
    });
    this.last = null;
    requestAnimationFrame((t) => this.tick(t));
  }

  setPlaying(playing) {
    this.playing = playing;
    this.playButton.textContent = playing ? "pause" : "play";
  }

  tick(now) {
    if (this.last !== null && this.playing) {
      this.time += ((now - this.last) / 1000) * this.speed;
      if (this.time > this.duration) this.time = 0;  // loop
      this.scrub.value = String(Math.round((this.time / Math.max(this.duration, 1e-9)) * 1000));
    }
    this.last = now;
    const follow = this.cameraSelect.value === "follow";
    for (const panel of this.panels) {
      panel.show(frameAt(panel.data.time, this.time), follow);
      panel.render();
    }
    this.rendered++;
    this.timeLabel.textContent = `${this.time.toFixed(2)} / ${this.duration.toFixed(2)} s`;
    this.statusNode.textContent = JSON.stringify({
      ready: true,
      rendered: this.rendered,
      playing: this.playing,
      time: this.time,
      panels: this.panels.map((p) => p.status()),
    });
    requestAnimationFrame((t) => this.tick(t));
  }
}

function start() {
  const statusNode = () => document.getElementById("cambrian-status");
  try {
    const data = JSON.parse(document.getElementById("cambrian-data").textContent);
    window.cambrianViewer = new Viewer(data.scenes, data.title || "cambrian");
  } catch (error) {
    const message = element("pre", { id: "cambrian-error" }, `cambrian viewer: ${error.message}`);
    document.body.append(message);
    const node = statusNode() || document.body.appendChild(element("pre", { id: "cambrian-status", hidden: "" }));
    node.textContent = JSON.stringify({ ready: false, error: String(error.message) });
  }
}

if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
else start();
