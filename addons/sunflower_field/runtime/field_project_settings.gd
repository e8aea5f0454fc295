@tool
extends RefCounted
## The addon's machine-wide settings, in Project Settings under [code]sunflower_field/[/code]: what a
## machine affords every field alike (the threads that move near plants, whether large maps build in
## the background, the main-thread time a build step may take, the frame budget every viewport's
## fields are held to together), so no scene carries them.
## Each has its row in the core's table (its default, limits and what a bad value becomes), named
## [code]"ProjectSettings." + the setting[/code]; a bad value is warned about once, naming the setting.
## A game may change them at run time ([method ProjectSettings.set_setting]); fields follow.

const Native: GDScript = preload("../native/native.gd")

## Threads that move the plants near the observer, the main thread included: 0 uses the machine's
## cores (at most 4), 1 keeps the work on the main thread.
const WORKER_THREADS: String = "sunflower_field/performance/worker_threads"
## Build large maps without stalling: read and laid out on a worker thread, their nodes made a few
## at a time, within [constant BUILD_BUDGET_MS] a frame.
const BACKGROUND_BUILD: String = "sunflower_field/performance/background_build"
## Main-thread milliseconds a background build may take a frame.
const BUILD_BUDGET_MS: String = "sunflower_field/performance/build_budget_ms"
## The frame budget (field_budget.gd): the most triangles the near meshes of a viewport's fields
## may hold in a frame together (0: no cap).
const BUDGET_PRIMITIVES: String = "sunflower_field/frame_budget/max_primitives"
## The frame budget: the milliseconds a viewport may take on the GPU a frame (0: no target).
const BUDGET_GPU_MS: String = "sunflower_field/frame_budget/gpu_ms"
## The frame budget: the least quality (share of the distances) it goes down to.
const BUDGET_MIN_QUALITY: String = "sunflower_field/frame_budget/min_quality"
## The settings with a row in the core's table (background_build, a switch, has none: on).
const TABLE_SETTINGS: PackedStringArray = [
	WORKER_THREADS, BUILD_BUDGET_MS, BUDGET_PRIMITIVES, BUDGET_GPU_MS, BUDGET_MIN_QUALITY
]
## What each setting was called when it was a SunflowerField property (scenes saved then still
## carry it: see [method SunflowerField._set]).
const FORMER_PROPERTIES: Dictionary = {
	&"worker_threads": WORKER_THREADS,
	&"background_build": BACKGROUND_BUILD,
	&"build_budget_ms": BUILD_BUDGET_MS,
	&"budget_primitives": BUDGET_PRIMITIVES,
	&"budget_gpu_ms": BUDGET_GPU_MS,
	&"budget_min_quality": BUDGET_MIN_QUALITY,
}
## The settings held as whole numbers.
const INTEGER_SETTINGS: PackedStringArray = [WORKER_THREADS, BUDGET_PRIMITIVES]

static var _warned: Dictionary = {}  # setting → the bad value last warned about


## Adds the settings to Project Settings (the editor plugin does, so they show there with their
## limits); a project that set one keeps its value.
static func register() -> void:
	for setting: String in TABLE_SETTINGS + PackedStringArray([BACKGROUND_BUILD]):
		var fallback: Variant = default_of(setting)
		if not ProjectSettings.has_setting(setting):
			ProjectSettings.set_setting(setting, fallback)
		ProjectSettings.set_initial_value(setting, fallback)
		ProjectSettings.set_as_basic(setting, true)
		var info: Dictionary = {"name": setting, "type": typeof(fallback)}
		if setting in TABLE_SETTINGS:
			info["hint"] = PROPERTY_HINT_RANGE
			info["hint_string"] = Native.range_hint(row(setting), "0,1,%s" % (1 if fallback is int else 0.01))
		ProjectSettings.add_property_info(info)


## The setting's default: its table row's, or on for [constant BACKGROUND_BUILD].
static func default_of(setting: String) -> Variant:
	if setting == BACKGROUND_BUILD:
		return true
	var value: float = Native.default_of(row(setting)) if Native.is_available() else 0.0
	return int(value) if setting in INTEGER_SETTINGS else value


## The worker threads a field uses now.
static func worker_threads() -> int:
	return int(_checked(WORKER_THREADS))


## Whether large maps build in the background now.
static func background_build() -> bool:
	return bool(ProjectSettings.get_setting(BACKGROUND_BUILD, true))


## The main-thread milliseconds a background build step may take now.
static func build_budget_ms() -> float:
	return _checked(BUILD_BUDGET_MS)


## The frame budget's cap on a viewport's near triangles a frame now (0: none).
static func budget_primitives() -> int:
	return int(_checked(BUDGET_PRIMITIVES))


## The frame budget's GPU-time target now, milliseconds (0: none).
static func budget_gpu_ms() -> float:
	return _checked(BUDGET_GPU_MS)


## The least quality the frame budget goes down to now.
static func budget_min_quality() -> float:
	return _checked(BUDGET_MIN_QUALITY)


## Whether a frame budget is set (a cap or a GPU-time target).
static func has_frame_budget() -> bool:
	return budget_primitives() > 0 or budget_gpu_ms() > 0.0


## The table row of [param setting].
static func row(setting: String) -> String:
	return "ProjectSettings." + setting


## [param setting]'s value by its row's rules; a value the rules change is warned about once.
static func _checked(setting: String) -> float:
	var fallback: float = float(default_of(setting))
	var value: Variant = ProjectSettings.get_setting(setting, fallback)
	var asked: float = float(value) if value is float or value is int else NAN
	var judged: Array = Native.judge(row(setting), asked, fallback)
	if not judged[1].is_empty() and _warned.get(setting, "") != str(value):
		_warned[setting] = str(value)
		push_warning("Project Settings %s: %s (%s)" % [setting, judged[1], value])
	return judged[0]
