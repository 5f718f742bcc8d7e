// pool.js: the pool table of cc_demo's pool scene (demo/scenes_pool.c), played with the mouse.
// The library does all of the physics: the cloth is the world's rolling deceleration, balls have
// restitution 0.95 and cushions 0.75 (CC_MIX_MIN), each pocket is an immovable sensor circle of
// radius (pocket radius - ball radius) whose begin event means the ball's centre is over the hole,
// and the aiming line and ghost ball come from cc_world_cast_circle_filtered, a cast that leaves
// the cue ball itself out (the object ball leaves along the cast's contact normal). Units: metres, seconds, kilograms.
import { load } from "./circlecollide.js";

const L = 2.54, W = 1.27; // playing area between the cushion noses
const R = 0.028575, M = 0.17; // ball radius and mass
const CORNER_GAP = 0.075, SIDE_GAP = 0.065, SIDE_DROP = 0.02, POCKET_R = 0.062;
const ROLL_DECEL = 0.15, BALL_E = 0.95, CUSHION_E = 0.75;
const CORNER_PIECES = 9, SIDE_PIECES = 8;
const WALLS = 6 + 4 * CORNER_PIECES + 2 * SIDE_PIECES;
const MARGIN = 0.13; // rails around the cloth, drawn
const DT = 1 / 60; // one world step per frame (scaled by ?steps=N)
const MAX_SPEED = 9; // a firm break is 8 m/s
const MAX_PULL = 0.45; // metres of pull-back for the full speed

const POCKETS = [[0, 0], [L, 0], [0, W], [L, W], [L / 2, -SIDE_DROP], [L / 2, W + SIDE_DROP]];
const CUSHIONS = [
  [CORNER_GAP, 0, L / 2 - SIDE_GAP, 0], [L / 2 + SIDE_GAP, 0, L - CORNER_GAP, 0],
  [CORNER_GAP, W, L / 2 - SIDE_GAP, W], [L / 2 + SIDE_GAP, W, L - CORNER_GAP, W],
  [0, CORNER_GAP, 0, W - CORNER_GAP], [L, CORNER_GAP, L, W - CORNER_GAP]];
// the ball numbers of the 15 rack places (apex first, row by row), the 8 in the middle
const RACK_NUMBERS = [1, 9, 2, 10, 8, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15];
const COLOURS = ["#f5f5ee", "#f2c21b", "#1d4fc2", "#d22b1f", "#5a2b8a", "#f07a18", "#17803d",
  "#7d1d22", "#141414"];

const params = new URLSearchParams(location.search);
const stepsPerFrame = Math.max(1, Math.min(16, Number(params.get("steps")) || 1));

const canvas = document.getElementById("table");
const ctx = canvas.getContext("2d");
const scoreEl = document.getElementById("score");
const statusEl = document.getElementById("status");
const powerEl = document.getElementById("power");
const versionEl = document.getElementById("version");
const scale = canvas.width / (L + 2 * MARGIN);
const sx = (x) => (x + MARGIN) * scale;
const sy = (y) => (W + MARGIN - y) * scale;

let lib, world;
let game; // everything that a reset starts again
let flashes = []; // contact flashes: {x, y, t0, strength}
const pendingPockets = new Set(); // ball ids over a hole during the last step (sensor callback)

function newGame() {
  if (game) world.init(); // a reset: a new world in the same memory (reserved once, at start)
  game = {
    numbers: new Map(), // ball id -> number (0: cue)
    cue: -1,
    pocketSensors: new Set(),
    potted: [],
    fouls: 0,
    shots: 0,
    state: "aim", // aim | pull | moving
    aim: { x: 1, y: 0 },
    mouse: null,
    pullFrom: null,
    pull: 0, // the pull's component against the aim, metres (0 .. MAX_PULL)
    note: "", // why the last release shot nothing, until the next press
    aimHit: null, // the aiming cast as last drawn
    lastShot: null, // {speed, x, y}: the last shot's speed and direction
    steps: 0,
    movedBalls: 0,
  };
  flashes = [];
  pendingPockets.clear();
  for (const c of CUSHIONS) world.segmentRestitution(world.addSegment(...c), CUSHION_E);
  const side = Math.asin(SIDE_DROP / POCKET_R) * 180 / Math.PI;
  pocketBack(0, 90, 270, CORNER_PIECES);
  pocketBack(1, 180, 270, CORNER_PIECES);
  pocketBack(2, 0, 270, CORNER_PIECES);
  pocketBack(3, 270, 270, CORNER_PIECES);
  pocketBack(4, 180 - side, 180 + 2 * side, SIDE_PIECES);
  pocketBack(5, -side, 180 + 2 * side, SIDE_PIECES);
  // the rack: apex on the foot spot, row k holds k + 1 balls, each touching its neighbours
  const row = Math.sqrt(3) * R, foot = 0.75 * L, cy = 0.5 * W;
  let place = 0;
  for (let k = 0; k < 5; k++)
    for (let j = 0; j <= k; j++) {
      const id = world.addCircle({ x: foot + k * row, y: cy + (2 * j - k) * R, radius: R, mass: M });
      world.circleRestitution(id, BALL_E);
      game.numbers.set(id, RACK_NUMBERS[place++]);
    }
  placeCue();
  for (const [x, y] of POCKETS) {
    const id = world.addCircle({ x, y, radius: POCKET_R - R, mass: Infinity });
    world.circleSensor(id);
    game.pocketSensors.add(id);
  }
  updateScore();
}

// the back of a pocket: walls along its rim from angle a0 through span (degrees)
function pocketBack(pocket, a0, span, pieces) {
  const [cx, cy] = POCKETS[pocket];
  for (let k = 0; k < pieces; k++) {
    const u = (a0 + span * k / pieces) * Math.PI / 180;
    const v = (a0 + span * (k + 1) / pieces) * Math.PI / 180;
    const id = world.addSegment(cx + POCKET_R * Math.cos(u), cy + POCKET_R * Math.sin(u),
      cx + POCKET_R * Math.cos(v), cy + POCKET_R * Math.sin(v));
    world.segmentRestitution(id, CUSHION_E);
  }
}

// the cue ball on the head spot, or the nearest free place along the head string
function placeCue() {
  const balls = world.circles().filter((c) => c.mass !== Infinity);
  let x = 0.25 * L, y = 0.5 * W;
  for (let k = 0; k < 40; k++) {
    const yk = y + (k % 2 ? 1 : -1) * Math.ceil(k / 2) * 2.5 * R;
    if (yk > R && yk < W - R && balls.every((b) => Math.hypot(b.x - x, b.y - yk) > 2.05 * R)) {
      y = yk;
      break;
    }
  }
  game.cue = world.addCircle({ x, y, radius: R, mass: M });
  world.circleRestitution(game.cue, BALL_E);
  game.numbers.set(game.cue, 0);
}

function updateScore() {
  const left = 15 - game.potted.length;
  scoreEl.textContent = `potted ${game.potted.length} · on the table ${left} · shots ${game.shots}` +
    ` · fouls ${game.fouls}`;
}

// ---- the world's callbacks: they only take notes (the world may not change inside a step) ----
function onContact(e) {
  if (flashes.length < 64 && e.impulse > 0.004)
    flashes.push({ x: e.px, y: e.py, t0: performance.now(), strength: Math.min(1, e.impulse / 0.5) });
}

function onSensor(e) {
  if (e.begin && game.pocketSensors.has(e.sensor) && game.numbers.has(e.visitor))
    pendingPockets.add(e.visitor);
}

// ---- simulation ----
function cueBall() {
  return game.cue < 0 ? null : world.circles().find((c) => c.id === game.cue) || null;
}

function shoot(speed) {
  const c = cueBall();
  if (!c) return;
  world.setCircle(game.cue, { x: c.x, y: c.y, vx: game.aim.x * speed, vy: game.aim.y * speed,
    radius: R, mass: M });
  game.lastShot = { speed, x: game.aim.x, y: game.aim.y };
  game.shots++;
  game.state = "moving";
  updateScore();
}

function advance() {
  for (let s = 0; s < stepsPerFrame && game.state === "moving"; s++) {
    world.step(DT);
    game.steps++;
    // the balls whose centre went over a hole leave the table before the next step
    for (const id of pendingPockets) {
      world.removeCircle(id);
      const n = game.numbers.get(id);
      game.numbers.delete(id);
      if (n === 0) {
        game.cue = -1;
        game.fouls++;
      } else {
        game.potted.push(n);
      }
    }
    if (pendingPockets.size) updateScore();
    pendingPockets.clear();
    if (world.circles().every((c) => c.vx === 0 && c.vy === 0)) {
      if (game.cue < 0) placeCue(); // a scratch: the cue ball comes back on the head spot
      game.state = "aim";
    }
  }
}

// ---- the mouse: aim, pull back for power, release to shoot ----
function tablePoint(ev) {
  const r = canvas.getBoundingClientRect();
  const px = (ev.clientX - r.left) * canvas.width / r.width;
  const py = (ev.clientY - r.top) * canvas.height / r.height;
  return { x: px / scale - MARGIN, y: W + MARGIN - py / scale };
}

function aimAt(p) {
  const c = cueBall();
  if (!c) return;
  const dx = p.x - c.x, dy = p.y - c.y, d = Math.hypot(dx, dy);
  if (d > 1e-6) game.aim = { x: dx / d, y: dy / d };
}

// (each handler waits for the module: before it loads there is no game)
// The pull: the mouse's way from where it was pressed. Only its component against the aim (back
// along the cue) gives power; the aim stays where the press put it. Read each move and shown
// while pulling (the stick, the bar, #power), so that a pull sideways or forward says why it
// gives little or none instead of doing nothing silently.
function pullOf(p) {
  const dx = p.x - game.pullFrom.x, dy = p.y - game.pullFrom.y;
  const back = -(dx * game.aim.x + dy * game.aim.y); // the component against the aim
  const pull = Math.max(0, Math.min(MAX_PULL, back));
  return { dx, dy, back, pull, speed: MAX_SPEED * pull / MAX_PULL };
}

function powerText() {
  if (game.state !== "pull") return game.note;
  const q = pullOf(game.mouse || game.pullFrom);
  const deg = Math.round(Math.atan2(game.aim.y, game.aim.x) * 180 / Math.PI);
  if (q.back <= 0)
    return `power 0 m/s: pull back along the cue (away from the aim at ${deg}°) for power`;
  const off = Math.hypot(q.dx, q.dy) > 1e-9 ? Math.round(Math.acos(Math.min(1, q.back / Math.hypot(q.dx, q.dy))) * 180 / Math.PI) : 0;
  return `power ${q.speed.toFixed(1)} m/s (${Math.round(100 * q.pull / MAX_PULL)} %) toward ${deg}°` +
    (off > 10 ? ` · the pull is ${off}° off the cue: only its part along the cue counts` : "");
}

canvas.addEventListener("mousedown", (ev) => {
  if (!game || game.state !== "aim" || ev.button !== 0) return;
  const p = tablePoint(ev);
  aimAt(p);
  game.state = "pull";
  game.pullFrom = p;
  game.mouse = p;
  game.pull = 0;
  game.note = "";
  ev.preventDefault();
});

window.addEventListener("mousemove", (ev) => {
  if (!game) return;
  const p = tablePoint(ev);
  game.mouse = p;
  if (game.state === "aim") aimAt(p);
  else if (game.state === "pull") game.pull = pullOf(p).pull;
});

window.addEventListener("mouseup", (ev) => {
  if (!game || game.state !== "pull" || ev.button !== 0) return;
  const speed = MAX_SPEED * game.pull / MAX_PULL;
  game.pull = 0;
  if (speed > 0.05) {
    shoot(speed);
  } else {
    game.state = "aim";
    game.note = "no shot: pull back along the cue, away from the aim, for power";
  }
});

document.getElementById("reset").addEventListener("click", () => game && newGame());

// ---- drawing ----
function disc(x, y, r, fill) {
  ctx.beginPath();
  ctx.arc(sx(x), sy(y), r * scale, 0, 2 * Math.PI);
  ctx.fillStyle = fill;
  ctx.fill();
}

function line(x0, y0, x1, y1, style, width, dash = []) {
  ctx.beginPath();
  ctx.moveTo(sx(x0), sy(y0));
  ctx.lineTo(sx(x1), sy(y1));
  ctx.strokeStyle = style;
  ctx.lineWidth = width;
  ctx.setLineDash(dash);
  ctx.stroke();
  ctx.setLineDash([]);
}

function drawBall(c, n) {
  if (n <= 8) {
    disc(c.x, c.y, R, COLOURS[n]);
  } else { // a stripe: white ball, coloured band
    disc(c.x, c.y, R, COLOURS[0]);
    ctx.save();
    ctx.beginPath();
    ctx.arc(sx(c.x), sy(c.y), R * scale, 0, 2 * Math.PI);
    ctx.clip();
    ctx.fillStyle = COLOURS[n - 8];
    ctx.fillRect(sx(c.x) - R * scale, sy(c.y) - 0.55 * R * scale, 2 * R * scale, 1.1 * R * scale);
    ctx.restore();
  }
  if (n > 0) {
    disc(c.x, c.y, 0.5 * R, "#fbfbf4");
    ctx.fillStyle = "#111";
    ctx.font = `bold ${Math.round(0.62 * R * scale)}px sans-serif`;
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillText(String(n), sx(c.x), sy(c.y) + 0.5);
  }
  ctx.beginPath();
  ctx.arc(sx(c.x), sy(c.y), R * scale, 0, 2 * Math.PI);
  ctx.strokeStyle = "rgba(0,0,0,0.35)";
  ctx.lineWidth = 1;
  ctx.stroke();
}

function drawAim(cue) {
  const reach = 3.2; // longer than the table's diagonal
  // the cue ball casts from where it is: the filter leaves it out (else it overlaps itself)
  const hit = world.cast(cue.x, cue.y, R, game.aim.x * reach, game.aim.y * reach, { ignore: game.cue });
  game.aimHit = hit;
  const t = hit ? hit.t : 1;
  const gx = cue.x + game.aim.x * reach * t, gy = cue.y + game.aim.y * reach * t;
  line(cue.x, cue.y, gx, gy, "rgba(255,255,255,0.75)", 1.5, [6, 5]);
  ctx.beginPath();
  ctx.arc(sx(gx), sy(gy), R * scale, 0, 2 * Math.PI);
  ctx.strokeStyle = "rgba(255,255,255,0.85)";
  ctx.lineWidth = 1.5;
  ctx.stroke();
  if (hit && hit.circle >= 0) {
    // the object ball leaves along the contact normal; the cue ball along the tangent
    const ob = world.circles().find((c) => c.id === hit.circle);
    if (ob) line(ob.x, ob.y, ob.x + hit.nx * 0.35, ob.y + hit.ny * 0.35, "rgba(255,235,120,0.9)", 2);
    const along = game.aim.x * hit.nx + game.aim.y * hit.ny;
    const tx = game.aim.x - along * hit.nx, ty = game.aim.y - along * hit.ny;
    line(gx, gy, gx + tx * 0.25, gy + ty * 0.25, "rgba(255,255,255,0.4)", 1.5, [3, 4]);
  }
  // the stick, drawn back by the pull
  const back = R + 0.02 + game.pull;
  line(cue.x - game.aim.x * back, cue.y - game.aim.y * back,
    cue.x - game.aim.x * (back + 1.1), cue.y - game.aim.y * (back + 1.1), "#c79a5b", 6);
  if (game.state === "pull") {
    const frac = game.pull / MAX_PULL;
    ctx.fillStyle = "rgba(0,0,0,0.45)";
    ctx.fillRect(12, canvas.height - 26, 204, 16);
    ctx.fillStyle = `hsl(${120 - 120 * frac}, 80%, 50%)`;
    ctx.fillRect(14, canvas.height - 24, 200 * frac, 12);
    ctx.fillStyle = "#fff";
    ctx.font = "13px sans-serif";
    ctx.textAlign = "left";
    ctx.textBaseline = "middle";
    ctx.fillText(`${(MAX_SPEED * frac).toFixed(1)} m/s`, 224, canvas.height - 18);
    // the pull as the mouse made it (thin), and the part of it that counts, along the cue
    const m = game.mouse || game.pullFrom, f = game.pullFrom;
    line(f.x, f.y, m.x, m.y, "rgba(255,255,255,0.5)", 1, [2, 3]);
    line(f.x, f.y, f.x - game.aim.x * game.pull, f.y - game.aim.y * game.pull, "rgba(255,120,70,0.95)", 3);
    // the shot's direction and power: an arrow from the cue ball along the aim
    const len = 0.05 + 0.3 * frac, tx = cue.x + game.aim.x * len, ty = cue.y + game.aim.y * len;
    line(cue.x, cue.y, tx, ty, `hsl(${120 - 120 * frac}, 80%, 55%)`, 3);
    const ax = -game.aim.y * 0.015, ay = game.aim.x * 0.015;
    line(tx, ty, tx - game.aim.x * 0.03 + ax, ty - game.aim.y * 0.03 + ay, `hsl(${120 - 120 * frac}, 80%, 55%)`, 3);
    line(tx, ty, tx - game.aim.x * 0.03 - ax, ty - game.aim.y * 0.03 - ay, `hsl(${120 - 120 * frac}, 80%, 55%)`, 3);
  }
}

function draw() {
  ctx.fillStyle = "#5c361e"; // rails
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = "#125434"; // cushions' outer edge
  ctx.fillRect(sx(-0.04), sy(W + 0.04), (L + 0.08) * scale, (W + 0.08) * scale);
  ctx.fillStyle = "#186e44"; // the cloth inside the cushion lines
  ctx.fillRect(sx(0), sy(W), L * scale, W * scale);
  disc(0.75 * L, 0.5 * W, 0.006, "rgba(255,255,255,0.5)"); // foot spot
  line(0.25 * L, 0, 0.25 * L, W, "rgba(255,255,255,0.12)", 1); // head string
  for (const [x, y] of POCKETS) disc(x, y, POCKET_R, "#08080a");
  for (const c of CUSHIONS) line(c[0], c[1], c[2], c[3], "#0d4026", 3);
  const now = performance.now();
  flashes = flashes.filter((f) => now - f.t0 < 250);
  for (const f of flashes) {
    const a = 1 - (now - f.t0) / 250;
    ctx.beginPath();
    ctx.arc(sx(f.x), sy(f.y), (0.4 + 0.8 * (1 - a)) * 2 * R * scale, 0, 2 * Math.PI);
    ctx.strokeStyle = `rgba(255,255,200,${0.7 * a * (0.4 + 0.6 * f.strength)})`;
    ctx.lineWidth = 2;
    ctx.stroke();
  }
  for (const c of world.circles()) {
    const n = game.numbers.get(c.id);
    if (n !== undefined) drawBall(c, n);
  }
  const cue = cueBall();
  if (cue && (game.state === "aim" || game.state === "pull")) drawAim(cue);
  powerEl.textContent = powerText();
  statusEl.textContent = game.state === "moving"
    ? `rolling… t = ${world.time().toFixed(2)} s`
    : game.potted.length === 15 ? "table cleared: press reset for a new rack"
    : "aim with the mouse, press and pull back for power, release to shoot";
}

function frame() {
  try {
    if (game.state === "moving") advance();
    draw();
  } catch (e) {
    console.error(e);
    statusEl.textContent = "error: " + e.message;
    return; // the loop stops: the page shows the error
  }
  requestAnimationFrame(frame);
}

// ---- start, and what the browser test reads (scripts/test.d/70-web.sh) ----
async function main() {
  lib = await load("circlecollide.wasm", { contact: onContact, sensor: onSensor });
  versionEl.textContent = "circlecollide " + lib.version() + " (WebAssembly)";
  world = lib.createWorld({ maxCircles: 16 + 6, maxSegments: WALLS, mode: "exact",
    restitution: BALL_E, restSpeed: 0.01, rollingDecel: ROLL_DECEL, restitutionMix: 0 });
  newGame();
  window.ccPage = {
    version: lib.version(),
    state: () => game.state,
    shots: () => game.shots,
    cueId: () => game.cue,
    // where a point of the table is in the window (client coordinates), for synthetic mouse input
    clientPoint: (x, y) => {
      const r = canvas.getBoundingClientRect();
      return { x: r.left + sx(x) * r.width / canvas.width, y: r.top + sy(y) * r.height / canvas.height };
    },
    potted: () => game.potted.slice(),
    // the pull now (state "pull"): its component against the aim, the speed it gives, the aim
    pull: () => game.state !== "pull" ? null : Object.assign(pullOf(game.mouse || game.pullFrom),
      { aim: { ...game.aim } }),
    lastShot: () => game.lastShot,
    // the aiming cast as last drawn: null (a miss) or {circle, segment, t, ..., overlap}
    aimHit: () => game.aimHit,
    fouls: () => game.fouls,
    worldBytes: () => world.bytes,
    powerText: () => powerEl.textContent,
    steps: () => game.steps,
    time: () => world.time(),
    balls: () => world.circles().filter((c) => game.numbers.has(c.id)),
    worldState: () => world.stateText(),
    journal: () => world.journalText(),
  };
  requestAnimationFrame(frame);
}

main().catch((e) => {
  console.error(e);
  statusEl.textContent = "could not start: " + e.message;
});
