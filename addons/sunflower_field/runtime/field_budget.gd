@tool
extends RefCounted
## Holds a field to a frame budget by one quality scalar (1: as configured, down to
## [member min_quality]) that scales the level-of-detail distances, the thinning start and the draw
## distance together. The cost is the larger share of either target: the near meshes' triangles the
## field wrote this frame against [member max_primitives], the viewport's measured GPU time against
## [member gpu_ms]. A near mesh's share grows with the square of the distances, so a step aims at a
## quality whose cost is a margin under the target. Over budget it steps down (at most
## [constant MAX_STEP_DOWN] a step); it steps up (at most [constant MAX_STEP_UP]) only after
## [constant HEADROOM_SECONDS] under [constant HEADROOM], and never above a quality that went over
## budget in the last [constant CEILING_SECONDS]: no pumping between two qualities.
##
## The budget is the viewport's, not a field's: every field drawn in one viewport shares one
## ([method governor_of]), with the project's targets (Project Settings,
## [code]sunflower_field/frame_budget/[/code]), the triangles of all their near meshes summed and the
## viewport's GPU time; it steps once a round (every field of the viewport has told its triangles),
## so that two fields do not both answer one overrun, and every field draws at its quality.

## Seconds between steps: a step's LOD pass has run and its cost shows before the next one.
const STEP_SECONDS: float = 0.25
## A step down aims at this share of the target; a step up at [constant UP_AIM].
const DOWN_AIM: float = 0.9
const UP_AIM: float = 0.8
## The largest change of one step, as a share of the quality.
const MAX_STEP_DOWN: float = 0.3
const MAX_STEP_UP: float = 0.1
## Below this share of the target for [constant HEADROOM_SECONDS], the quality may rise.
const HEADROOM: float = 0.7
const HEADROOM_SECONDS: float = 1.0
## How long a quality that went over budget stays the ceiling for steps up.
const CEILING_SECONDS: float = 10.0
## The GPU time is smoothed over about this many seconds (it jitters frame to frame).
const GPU_SMOOTHING_SECONDS: float = 0.15

const ProjectKnobs: GDScript = preload("field_project_settings.gd")

static var _governors: Dictionary = {}  # viewport RID → the budget its fields share

## The cap on the near meshes' triangles a frame (0: none).
var max_primitives: int = 0
## The target for the viewport's GPU time a frame, in milliseconds (0: none).
var gpu_ms: float = 0.0
## The least quality the field goes down to.
var min_quality: float = 0.25
## The quality now: the share of the configured distances the field draws with.
var quality: float = 1.0
## The last costs seen: triangles of the near meshes, and the smoothed GPU time (0 before one).
var primitives: int = 0
var smoothed_gpu_ms: float = 0.0

var _since_step: float = 0.0
var _under_for: float = 0.0
var _ceiling: float = INF
var _ceiling_age: float = 0.0

var _round: Dictionary = {}  # field (instance id) → its near triangles in the round being summed
var _called_frame: int = -1  # the process frame a field last stepped it in


## The budget every field drawn in the viewport [param viewport] shares.
static func governor_of(viewport: RID) -> RefCounted:
	if not _governors.has(viewport):
		_governors[viewport] = new()
	return _governors[viewport]


## One frame of a viewport's shared budget (see [method governor_of]), called by each field drawn
## there with the triangles its near meshes held [param field_primitives] and the viewport's GPU time
## [param frame_gpu_ms] (0: not measured). A field calling again completes the round: the budget
## steps, with the project's targets, on the round's triangles summed over its fields. A budget no
## field stepped in the last frame starts afresh (full quality: fields that come back, or a budget
## set again, are not held where it left off). True when it stepped and the quality changed.
func step_shared(delta: float, field: Object, field_primitives: int, frame_gpu_ms: float) -> bool:
	var frame: int = Engine.get_process_frames()
	if _called_frame >= 0 and frame - _called_frame > 1:  # no field stepped it last frame: start afresh
		quality = 1.0
		smoothed_gpu_ms = 0.0
		retarget()
		_round.clear()
	_called_frame = frame
	var key: int = field.get_instance_id()
	var changed: bool = false
	if _round.has(key):
		var total: int = 0
		for triangles: int in _round.values():
			total += triangles
		_round.clear()
		changed = _step_with_project_targets(delta, total, frame_gpu_ms)
	_round[key] = field_primitives
	return changed


## A step with the targets of Project Settings (a changed one is judged afresh; none: full quality).
func _step_with_project_targets(delta: float, total: int, frame_gpu_ms: float) -> bool:
	var cap: int = ProjectKnobs.budget_primitives()
	var target: float = ProjectKnobs.budget_gpu_ms()
	if cap != max_primitives or not is_equal_approx(target, gpu_ms):
		retarget()
	max_primitives = cap
	gpu_ms = target
	min_quality = ProjectKnobs.budget_min_quality()
	if not is_active():
		var was: float = quality
		quality = 1.0
		smoothed_gpu_ms = 0.0
		return was != quality
	return step(delta, total, frame_gpu_ms)


## Whether a target is set.
func is_active() -> bool:
	return max_primitives > 0 or gpu_ms > 0.0


## Forgets what the old targets taught (the ceiling, the time under them): a new target is judged
## afresh.
func retarget() -> void:
	_ceiling = INF
	_under_for = 0.0


## One frame of [param delta] seconds whose near meshes held [param frame_primitives] triangles and
## whose viewport took [param frame_gpu_ms] on the GPU (0: not measured), with a target set (the
## field gives all quality back itself when the targets go). True when the quality changed.
func step(delta: float, frame_primitives: int, frame_gpu_ms: float) -> bool:
	primitives = frame_primitives
	if frame_gpu_ms > 0.0:
		var weight: float = 1.0 if smoothed_gpu_ms == 0.0 else 1.0 - exp(-delta / GPU_SMOOTHING_SECONDS)
		smoothed_gpu_ms = lerpf(smoothed_gpu_ms, frame_gpu_ms, weight)
	_since_step += delta
	_ceiling_age += delta
	if _ceiling_age > CEILING_SECONDS:
		_ceiling = INF
	var load: float = load_share()
	_under_for = _under_for + delta if load < HEADROOM else 0.0
	if _since_step < STEP_SECONDS:
		return false
	_since_step = 0.0
	var wanted: float = quality
	if load > 1.0:
		wanted = quality * maxf(sqrt(DOWN_AIM / load), 1.0 - MAX_STEP_DOWN)
		_ceiling = quality
		_ceiling_age = 0.0
	elif _under_for >= HEADROOM_SECONDS and quality < 1.0:
		var room: float = sqrt(UP_AIM / load) if load > 0.0 else INF
		wanted = minf(quality * minf(room, 1.0 + MAX_STEP_UP), _ceiling * (1.0 - MAX_STEP_UP * 0.5))
		_under_for = 0.0
	wanted = clampf(wanted, min_quality, 1.0)
	if is_equal_approx(wanted, quality) or (load <= 1.0 and wanted < quality):
		return false
	quality = wanted
	return true


## The cost now as a share of its target, the larger of the two (0 with no target).
func load_share() -> float:
	var share: float = 0.0
	if max_primitives > 0:
		share = float(primitives) / max_primitives
	if gpu_ms > 0.0:
		share = maxf(share, smoothed_gpu_ms / gpu_ms)
	return share
