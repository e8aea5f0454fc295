class_name TestCase
extends RefCounted
## Base of the integration tests: methods named test_* are run in order; checks record failures
## with the file and line of the failing check.

var tree: SceneTree
## The runner's log of engine errors and warnings (see [method take_warnings]).
var log: Object
var failures: PackedStringArray = []
## Substrings of engine errors this test provokes on purpose; any other error fails the test.
var allowed_errors: PackedStringArray = []
var _project_settings: Dictionary = {}  # what set_project_setting changed → its value before


func before_each() -> void:
	pass


func after_each() -> void:
	pass


## Sets a Project Settings value for this test; the runner puts it back after the test.
func set_project_setting(setting: String, value: Variant) -> void:
	if not _project_settings.has(setting):
		_project_settings[setting] = (
			ProjectSettings.get_setting(setting) if ProjectSettings.has_setting(setting) else null
		)
	ProjectSettings.set_setting(setting, value)


## (The runner calls this after each test.) Puts back what [method set_project_setting] changed.
func restore_project_settings() -> void:
	for setting: String in _project_settings:
		ProjectSettings.set_setting(setting, _project_settings[setting])  # null removes it
	_project_settings.clear()


## Where a test writes [param file] (a path under tests/artifacts/, or under the folder the
## environment's TEST_ARTIFACTS names; made as needed), for a reader to look at after the run.
func artifact_path(file: String) -> String:
	var folder: String = OS.get_environment("TEST_ARTIFACTS")
	if folder.is_empty():
		folder = ProjectSettings.globalize_path("res://").path_join("../artifacts")
	var path: String = folder.path_join(file).simplify_path()
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	return path


## A field of [param map] in the tree, measuring distances from [param observer] (which joins the
## tree first), built and updated once.
func field_in_tree(observer: Node3D, map: SunflowerFieldMap) -> SunflowerField:
	tree.root.add_child(observer)
	var field: SunflowerField = SunflowerField.new()
	field.observer = NodePath("../" + observer.name)
	tree.root.add_child(field)
	field.map = map
	field.advance(0.0)
	return field


## The warnings the engine logged since the last call (or since the test began).
func take_warnings() -> PackedStringArray:
	return log.call("take_warnings")


## True when a warning logged since the last call contains [param fragment].
func warned(fragment: String) -> bool:
	for warning: String in take_warnings():
		if warning.contains(fragment):
			return true
	return false


## Lets engine errors containing [param fragment] happen during this test (bad input on purpose).
func allow_error(fragment: String) -> void:
	allowed_errors.append(fragment)


## Checks that the engine reported an error containing [param fragment] during this test (and lets it).
func expect_engine_error(fragment: String) -> bool:
	allow_error(fragment)
	for error: String in log.call("peek"):
		if error.contains(fragment):
			return true
	return check(false, "no engine error said '%s'" % fragment)


func check(condition: bool, message: String = "") -> bool:
	if not condition:
		failures.append("%s: %s" % [_caller(), message if message else "check failed"])
	return condition


func check_eq(actual: Variant, expected: Variant, message: String = "") -> bool:
	var same: bool = typeof(actual) == typeof(expected) and actual == expected
	if not same:
		failures.append("%s: %s expected %s, got %s" % [_caller(), message + ":" if message else "", expected, actual])
	return same


func check_near(actual: float, expected: float, tolerance: float, message: String = "") -> bool:
	var close: bool = absf(actual - expected) <= tolerance
	if not close:
		failures.append(
			(
				"%s: %s expected %s ± %s, got %s"
				% [_caller(), message + ":" if message else "", expected, tolerance, actual]
			)
		)
	return close


func frames(count: int = 1) -> void:
	for i: int in count:
		await tree.process_frame


## Waits frame by frame, at most [param limit] frames, until [param condition] returns true;
## returns the frames waited ([param limit] when it never did).
func frames_until(condition: Callable, limit: int) -> int:
	for i: int in limit:
		if condition.call():
			return i
		await tree.process_frame
	return limit


func _caller() -> String:
	for frame: Dictionary in get_stack():
		var source: String = frame["source"]
		if not source.ends_with("test_case.gd"):
			return "%s:%d" % [source, frame["line"]]
	return "?"
