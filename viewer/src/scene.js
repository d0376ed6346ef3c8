// The 3D view: each piece a mesh in its colour with its number, orbit/zoom/pan, picking, the
// selected piece and the pieces of the current build step emphasised, the seams to glue drawn.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';

const SELECT_GLOW = new THREE.Color(0x6a4800);
const PARTNER_GLOW = new THREE.Color(0x103a70);
const NEW_GLOW = new THREE.Color(0x3a1800);
const NO_GLOW = new THREE.Color(0x000000);

// Where a piece's number goes: among its triangles about as near its area-weighted centroid as
// the nearest (all of them round a tube), the one that faces `toward` (the first view) most;
// and the piece's outward direction there.
function anchorOf(points, triangles, toward) {
  const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
  const centroid = new THREE.Vector3(), normalSum = new THREE.Vector3();
  const centres = [], normals = [];
  let area = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    a.fromArray(points, 3 * triangles[t]);
    b.fromArray(points, 3 * triangles[t + 1]);
    c.fromArray(points, 3 * triangles[t + 2]);
    const normal = new THREE.Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a));
    const twiceArea = normal.length();
    const centre = a.clone().add(b).add(c).divideScalar(3);
    centres.push(centre);
    normals.push(twiceArea > 0 ? normal.clone().divideScalar(twiceArea) : normal);
    centroid.addScaledVector(centre, twiceArea);
    normalSum.add(normal);
    area += twiceArea;
  }
  if (!centres.length) return { position: centroid, normal: new THREE.Vector3() };
  if (area > 0) centroid.divideScalar(area);
  const distances = centres.map((centre) => centre.distanceTo(centroid));
  const nearest = distances.reduce((least, d) => Math.min(least, d), Infinity);
  const extent = new THREE.Box3().setFromArray(points).getSize(new THREE.Vector3()).length();
  let best = -1;
  for (let i = 0; i < centres.length; ++i) {
    if (distances[i] > nearest + 0.15 * extent) continue;
    if (best < 0 || normals[i].dot(toward) > normals[best].dot(toward) + 1e-9) best = i;
  }
  // A nearly flat piece faces along its summed normal; a curled one along its anchor triangle's.
  const normal = normalSum.length() > 0.3 * area ? normalSum.normalize() : normals[best];
  return { position: centres[best], normal };
}

function numberSprite(text, height) {
  const canvas = document.createElement('canvas');
  const context = canvas.getContext('2d');
  const font = 'bold 56px sans-serif';
  context.font = font;
  const width = Math.ceil(context.measureText(text).width) + 24;
  canvas.width = width;
  canvas.height = 72;
  context.font = font;
  context.fillStyle = 'rgba(255,255,255,0.85)';
  context.beginPath();
  context.roundRect(2, 2, width - 4, 68, 16);
  context.fill();
  context.fillStyle = '#111';
  context.textAlign = 'center';
  context.textBaseline = 'middle';
  context.fillText(text, width / 2, 38);
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  const material = new THREE.SpriteMaterial({ map: texture, depthWrite: false });
  const sprite = new THREE.Sprite(material);
  sprite.scale.set((height * width) / 72, height, 1);
  return sprite;
}

export class ModelView {
  constructor(container, model, onPick) {
    this.model = model;
    this.onPick = onPick;
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xeef1f3);
    container.prepend(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e6);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 1.6));
    const light = new THREE.DirectionalLight(0xffffff, 1.4);
    light.position.set(0.4, 0.6, 1);
    this.camera.add(light);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());
    this.meshes = new Map();
    this.anchors = new Map();
    this.sprites = new Map();
    this.seamLines = null;
    this.buildMeshes();
    this.frame();
    this.listen();
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  buildMeshes() {
    const box = new THREE.Box3();
    for (const piece of this.model.pieces) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(piece.points, 3));
      geometry.setIndex(new THREE.BufferAttribute(piece.triangles, 1));
      geometry.computeBoundingBox();
      box.union(geometry.boundingBox);
      const colour = new THREE.Color(piece.colour);
      const material = new THREE.MeshLambertMaterial({
        color: colour, side: THREE.DoubleSide, flatShading: true,
        polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
      });
      const mesh = new THREE.Mesh(geometry, material);
      mesh.userData = { piece, colour };
      this.meshes.set(piece.name, mesh);
      this.scene.add(mesh);
    }
    this.box = box.isEmpty() ? new THREE.Box3(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1)) : box;
    this.size = this.box.getSize(new THREE.Vector3()).length();
    const { toward } = this.firstView();
    for (const piece of this.model.pieces) {
      const anchor = anchorOf(piece.points, piece.triangles, toward);
      this.anchors.set(piece.name, anchor);
      // As tall as 3.5% of the model, less on a small piece, so that numbers stay apart.
      const extent = this.meshes.get(piece.name).geometry.boundingBox.getSize(new THREE.Vector3()).length();
      const sprite = numberSprite(piece.name, Math.min(0.035 * this.size, 0.3 * extent));
      sprite.position.copy(anchor.position).addScaledVector(anchor.normal, 0.01 * this.size);
      sprite.renderOrder = 2;
      this.sprites.set(piece.name, sprite);
      this.scene.add(sprite);
    }
  }

  // The first view: from the front, a little to the side and above. Up is z unless the model
  // is flattest along z (then y), as in the printed guide.
  firstView() {
    const extent = this.box.getSize(new THREE.Vector3());
    const up = extent.z <= Math.min(extent.x, extent.y) ? new THREE.Vector3(0, 1, 0) : new THREE.Vector3(0, 0, 1);
    const toward = up.z ? new THREE.Vector3(0.55, -1, 0.45) : new THREE.Vector3(0.55, 0.45, 1);
    return { up, toward: toward.normalize() };
  }

  // The whole model in the first view.
  frame() {
    const centre = this.box.getCenter(new THREE.Vector3());
    const distance = (0.5 * this.size) / Math.tan((this.camera.fov * Math.PI) / 360) * 1.15;
    const { up, toward } = this.firstView();
    this.camera.up.copy(up);
    this.camera.position.copy(centre).addScaledVector(toward, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    if (this.seamLines) this.seamLines.material.resolution.set(width, height);
    this.render();
  }

  render() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.renderNow();
    });
  }

  renderNow() {
    this.renderer.render(this.scene, this.camera);
    if (this.onFirstRender) {
      const callback = this.onFirstRender;
      this.onFirstRender = null;
      callback();
    }
  }

  listen() {
    const canvas = this.renderer.domElement;
    let down = null;
    canvas.addEventListener('pointerdown', (event) => {
      down = { x: event.clientX, y: event.clientY };
    });
    canvas.addEventListener('pointerup', (event) => {
      if (!down || Math.hypot(event.clientX - down.x, event.clientY - down.y) > 5) return;
      down = null;
      const hit = this.pieceAt(event.clientX, event.clientY);
      this.onPick(hit ? hit.name : null);
    });
  }

  // The visible piece under a point of the window, with the 3D point hit.
  pieceAt(clientX, clientY) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1,
                                      -((clientY - rect.top) / rect.height) * 2 + 1);
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(pointer, this.camera);
    const visible = [...this.meshes.values()].filter((mesh) => mesh.visible);
    const hits = raycaster.intersectObjects(visible, false);
    return hits.length ? { name: hits[0].object.userData.piece.name, point: hits[0].point } : null;
  }

  // Where a piece's anchor lies in the window, and whether it is the first thing seen there.
  screenPointOf(name) {
    const anchor = this.anchors.get(name);
    if (!anchor) return null;
    this.camera.updateMatrixWorld();
    const projected = anchor.position.clone().project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    const x = rect.left + ((projected.x + 1) / 2) * rect.width;
    const y = rect.top + ((1 - projected.y) / 2) * rect.height;
    const inside = Math.abs(projected.x) < 1 && Math.abs(projected.y) < 1 && projected.z < 1;
    const onCanvas = inside && document.elementFromPoint(x, y) === this.renderer.domElement;
    const hit = onCanvas ? this.pieceAt(x, y) : null;
    return { x, y, visible: Boolean(hit && hit.name === name) };
  }

  // Turns the camera round the model's centre to look at the piece from outside.
  turnTo(name) {
    const anchor = this.anchors.get(name);
    if (!anchor) return;
    const target = this.controls.target;
    const distance = this.camera.position.distanceTo(target);
    // Pieces face out (their triangles are wound so, docs/pieces.md): look along the normal.
    const direction = anchor.normal.clone();
    if (direction.lengthSq() === 0) direction.copy(anchor.position).sub(target);
    direction.normalize();
    // Straight along the up axis the orbit has no "around": tilt a little towards the camera.
    if (Math.abs(direction.dot(this.camera.up)) > 0.97) {
      const around = this.camera.position.clone().sub(target).projectOnPlane(this.camera.up);
      if (around.lengthSq() === 0) around.set(1, 0, 0).projectOnPlane(this.camera.up);
      direction.addScaledVector(around.normalize(), 0.3).normalize();
    }
    this.camera.position.copy(target).addScaledVector(direction, distance);
    this.controls.update();
    this.render();
  }

  // Shows the pieces of steps 1..k; the new piece glows and the seams to glue are drawn.
  showStep(step, built) {
    for (const [name, mesh] of this.meshes) {
      const piece = mesh.userData.piece;
      mesh.visible = piece.step <= step;
      this.sprites.get(name).visible = mesh.visible;
      const isNew = piece.step === step;
      const colour = mesh.userData.colour.clone();
      if (step < this.model.steps.length && !isNew) colour.lerp(new THREE.Color(0xffffff), 0.5);
      mesh.material.color.copy(colour);
      mesh.userData.isNew = isNew;
    }
    this.drawSeams(built);
    this.refreshGlow();
  }

  // Thick lines along the given seams: [{piece, label}] on that piece's side.
  drawSeams(seams) {
    if (this.seamLines) {
      this.scene.remove(this.seamLines);
      this.seamLines.geometry.dispose();
      this.seamLines = null;
    }
    const positions = [];
    for (const { piece, label } of seams) {
      for (const seam of piece.seams) {
        if (seam.label !== label) continue;
        for (let e = 0; e < seam.edges.length; e += 2)
          for (const v of [seam.edges[e], seam.edges[e + 1]])
            positions.push(piece.points[3 * v], piece.points[3 * v + 1], piece.points[3 * v + 2]);
      }
    }
    if (!positions.length) return this.render();
    const geometry = new LineSegmentsGeometry();
    geometry.setPositions(positions);
    const material = new LineMaterial({ color: 0xe0482f, linewidth: 4, depthTest: false });
    material.resolution.set(this.container.clientWidth, this.container.clientHeight);
    this.seamLines = new LineSegments2(geometry, material);
    this.seamLines.renderOrder = 3;
    this.scene.add(this.seamLines);
    this.render();
  }

  select(name) {
    this.selected = name;
    this.refreshGlow();
  }

  highlightPartner(name) {
    this.partner = name;
    this.refreshGlow();
  }

  refreshGlow() {
    for (const [name, mesh] of this.meshes) {
      const glow = name === this.selected ? SELECT_GLOW
        : name === this.partner ? PARTNER_GLOW
          : mesh.userData.isNew ? NEW_GLOW : NO_GLOW;
      mesh.material.emissive.copy(glow);
      // The selected piece's number shows through whatever hides it.
      const sprite = this.sprites.get(name);
      sprite.material.depthTest = name !== this.selected;
      sprite.renderOrder = name === this.selected ? 4 : 2;
    }
    this.render();
  }

  // Names of the pieces drawn, and of the one drawn as selected (for tests and tools).
  visibleNames() {
    return [...this.meshes.values()].filter((mesh) => mesh.visible).map((mesh) => mesh.userData.piece.name);
  }

  glowingAsSelected() {
    return [...this.meshes.values()]
      .filter((mesh) => mesh.material.emissive.equals(SELECT_GLOW))
      .map((mesh) => mesh.userData.piece.name);
  }
}
