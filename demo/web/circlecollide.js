// circlecollide.js: loads circlecollide.wasm (scripts/wasm.sh) and wraps the world for the page.
// The world lives in WebAssembly memory that is reserved once, at creation (web_alloc); the
// page reads every circle's position each frame with one call (circles()). Every call that
// changes the world is written to a journal, one line per call with every number as the
// 16 hex digits of its IEEE 754 bits, so that tests/web/replay.c can repeat the page's session
// with the native library and compare the results bit for bit (scripts/test.d/70-web.sh).

const CIRCLE_BYTES = 48; // cc_circle: pos, vel, radius, mass (six doubles)
const HIT_BYTES = 48; // cc_cast_hit: circle, segment (int32), t, point, normal

const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);

// the bits of a double as 16 hex digits (what the journal and the state report hold)
export function hex(x) {
  f64[0] = x;
  return u64[0].toString(16).padStart(16, "0");
}

export async function load(url, handlers) {
  const imports = {
    env: {
      on_contact: (a, b, seg, t, px, py, nx, ny, impulse) =>
        handlers.contact && handlers.contact({ a, b, segment: seg, t, px, py, nx, ny, impulse }),
      on_sensor: (sensor, visitor, begin, t) =>
        handlers.sensor && handlers.sensor({ sensor, visitor, begin: begin !== 0, t }),
    },
  };
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  const { instance } = await WebAssembly.instantiate(await response.arrayBuffer(), imports);
  return new Library(instance.exports);
}

class Library {
  constructor(x) {
    this.x = x;
    if (x.web_sizeof(0) !== CIRCLE_BYTES || x.web_sizeof(1) !== HIT_BYTES)
      throw new Error("circlecollide.wasm: unexpected struct sizes");
  }

  string(ptr) {
    const bytes = new Uint8Array(this.x.memory.buffer, ptr);
    let n = 0;
    while (bytes[n] !== 0) n++;
    return new TextDecoder().decode(bytes.subarray(0, n));
  }

  version() {
    return this.string(this.x.cc_version_string());
  }

  resultString(code) {
    return this.string(this.x.cc_result_string(code));
  }

  // def: {maxCircles, maxSegments, mode, restitution, restSpeed, rollingDecel, restitutionMix}
  createWorld(def) {
    return new World(this, def);
  }
}

const MODES = { exact: 0, swept: 1, discrete: 2 };

export class World {
  constructor(lib, def) {
    const x = lib.x;
    this.lib = lib;
    this.x = x;
    this.journal = [];
    this.capacity = def.maxCircles;
    const args = [def.maxCircles, def.maxSegments, MODES[def.mode || "exact"], def.restitution,
      def.restSpeed || 0, def.rollingDecel || 0, def.restitutionMix || 0, 1];
    x.web_def(...args);
    this.log("def", args.slice(0, 3).map(String).concat(args.slice(3, 6).map(hex),
      args.slice(6).map(String)));
    const bytes = x.web_world_size();
    if (bytes === 0) throw new Error("cc_world_size: the def is invalid");
    // the one reservation: the world, then scratch space for structs and the frame's arrays
    const scratch = 64 + HIT_BYTES + this.capacity * (CIRCLE_BYTES + 4);
    const base = x.web_alloc(bytes + 16 + scratch);
    if (base === 0) throw new Error("web_alloc: out of memory");
    this.base = base;
    this.bytes = bytes;
    this.init();
    let p = (base + bytes + 15) & ~15;
    this.circlePtr = p; p += 64;
    this.hitPtr = p; p += HIT_BYTES;
    this.outPtr = p; p += this.capacity * CIRCLE_BYTES;
    this.idsPtr = p;
  }

  // (again) an empty world in the same memory: what the page's reset does
  init() {
    this.w = this.x.web_world_init(this.base, this.bytes);
    this.log("init", [], this.w === 0 ? this.x.web_status() : 0);
    if (this.w === 0) throw new Error("cc_world_init: " + this.lib.resultString(this.x.web_status()));
  }

  log(op, args, result) {
    this.journal.push(op + (args.length ? " " + args.join(" ") : "") +
      (result === undefined ? "" : " = " + result));
  }

  f64(ptr, n) {
    return new Float64Array(this.x.memory.buffer, ptr, n);
  }

  check(what, r) {
    if (r < 0) throw new Error(`${what}: ${this.lib.resultString(r)}`);
    return r;
  }

  writeCircle(c) {
    const v = this.f64(this.circlePtr, 6);
    v[0] = c.x; v[1] = c.y; v[2] = c.vx || 0; v[3] = c.vy || 0; v[4] = c.radius;
    v[5] = c.mass === undefined ? 1 : c.mass;
    return Array.from(v, hex);
  }

  addCircle(c) {
    const args = this.writeCircle(c);
    const r = this.x.cc_world_add_circle(this.w, this.circlePtr);
    this.log("add_circle", args, r);
    return this.check("cc_world_add_circle", r);
  }

  setCircle(id, c) {
    const args = this.writeCircle(c);
    const r = this.x.cc_world_set_circle(this.w, id, this.circlePtr);
    this.log("set_circle", [String(id)].concat(args), r);
    return this.check("cc_world_set_circle", r);
  }

  removeCircle(id) {
    const r = this.x.cc_world_remove_circle(this.w, id);
    this.log("remove_circle", [String(id)], r);
    return this.check("cc_world_remove_circle", r);
  }

  addSegment(ax, ay, bx, by) {
    const v = this.f64(this.circlePtr, 4);
    v[0] = ax; v[1] = ay; v[2] = bx; v[3] = by;
    const r = this.x.cc_world_add_segment(this.w, this.circlePtr);
    this.log("add_segment", Array.from(v, hex), r);
    return this.check("cc_world_add_segment", r);
  }

  circleRestitution(id, e) {
    const r = this.x.web_circle_restitution(this.w, id, e);
    this.log("circle_restitution", [String(id), hex(e)], r);
    return this.check("cc_world_set_circle_props", r);
  }

  circleSensor(id) {
    const r = this.x.web_circle_sensor(this.w, id);
    this.log("circle_sensor", [String(id)], r);
    return this.check("cc_world_set_circle_props", r);
  }

  circleCategory(id, category) {
    const r = this.x.web_circle_category(this.w, id, category >>> 0);
    this.log("circle_category", [String(id), String(category >>> 0)], r);
    return this.check("cc_world_set_circle_props", r);
  }

  segmentRestitution(id, e) {
    const r = this.x.web_segment_restitution(this.w, id, e);
    this.log("segment_restitution", [String(id), hex(e)], r);
    return this.check("cc_world_set_segment_props", r);
  }

  step(dt) {
    const r = this.x.cc_world_step(this.w, dt);
    this.log("step", [hex(dt)], r);
    return this.check("cc_world_step", r);
  }

  time() {
    return this.x.cc_world_time(this.w);
  }

  hash() {
    return BigInt.asUintN(64, this.x.cc_world_hash(this.w));
  }

  // every circle now: [{id, x, y, vx, vy, radius, mass}], in the world's order
  circles() {
    const n = this.check("cc_world_get_circles",
      this.x.cc_world_get_circles(this.w, this.idsPtr, this.outPtr, this.capacity));
    const ids = new Int32Array(this.x.memory.buffer, this.idsPtr, n);
    const v = this.f64(this.outPtr, 6 * n);
    const out = [];
    for (let i = 0; i < n; i++) {
      const k = 6 * i;
      out.push({ id: ids[i], x: v[k], y: v[k + 1], vx: v[k + 2], vy: v[k + 3], radius: v[k + 4],
        mass: v[k + 5] });
    }
    return out;
  }

  // cc_world_cast_circle_filtered: null for a miss, else {circle, segment, t, px, py, nx, ny,
  // overlap}; the filter's mask (every category by default) and ignore, the id of a circle the
  // cast leaves out (-1: none), as the cue ball's own aiming cast needs
  cast(px, py, radius, dx, dy, { mask = 0xffffffff, ignore = -1 } = {}) {
    const r = this.check("cc_world_cast_circle_filtered",
      this.x.web_cast_circle(this.w, px, py, radius, dx, dy, mask >>> 0, ignore | 0, this.hitPtr));
    if (r === 0) return null;
    const ints = new Int32Array(this.x.memory.buffer, this.hitPtr, 2);
    const v = this.f64(this.hitPtr + 8, 5);
    return { circle: ints[0], segment: ints[1], t: v[0], px: v[1], py: v[2], nx: v[3], ny: v[4],
      overlap: r === 2 };
  }

  // the state the native replay prints: world time, hash, each circle's position and velocity
  stateText() {
    const lines = ["time " + hex(this.time()), "hash " + this.hash().toString(16).padStart(16, "0")];
    for (const c of this.circles())
      lines.push(["circle", c.id, hex(c.x), hex(c.y), hex(c.vx), hex(c.vy)].join(" "));
    return lines.join("\n") + "\n";
  }

  journalText() {
    return this.journal.join("\n") + "\n";
  }
}
