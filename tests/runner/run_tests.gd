extends SceneTree
## Runs every test_*.gd in res://cases/ or res://tests/cases/ (or those named after --: a file
## "test_render", a test "test_render.test_lone_plant", or a pattern with * and ? matched against
## either, e.g. "*lone*"; "!" before any of these leaves it out), prints each failure with its file
## and line, and ends with the line "godot: N passed, N failed".
## Exit code 1 on any failure.
## An engine or script error during a test fails it, unless the test allowed it (allow_error).


## Collects every error the engine reports (script errors included), from any thread.
class ErrorLog:
	extends Logger
	var _mutex: Mutex = Mutex.new()
	var _errors: PackedStringArray = []
	var _warnings: PackedStringArray = []

	func _log_error(
		function: String,
		file: String,
		line: int,
		code: String,
		rationale: String,
		_editor_notify: bool,
		error_type: int,
		_script_backtraces: Array[ScriptBacktrace]
	) -> void:
		_mutex.lock()
		var text: String = "%s (%s:%d %s)" % [rationale if rationale else code, file, line, function]
		if error_type == ERROR_TYPE_WARNING:
			_warnings.append(text)
		else:
			_errors.append(text)
		_mutex.unlock()

	func take() -> PackedStringArray:
		_mutex.lock()
		var errors: PackedStringArray = _errors
		_errors = []
		_mutex.unlock()
		return errors

	func peek() -> PackedStringArray:
		_mutex.lock()
		var errors: PackedStringArray = _errors.duplicate()
		_mutex.unlock()
		return errors

	func take_warnings() -> PackedStringArray:
		_mutex.lock()
		var warnings: PackedStringArray = _warnings
		_warnings = []
		_mutex.unlock()
		return warnings


## How long the emptied tree keeps drawing before the runner quits (see the end of _run).
const EXIT_SETTLE_SECONDS: float = 3.0

var _log: ErrorLog = ErrorLog.new()


## Whether a test is among those named: by its file, by file.method, or by a pattern matching either;
## an entry starting with "!" leaves out what it matches (no other entry: every test but those).
static func _is_wanted(wanted: PackedStringArray, file: String, method: String) -> bool:
	var chosen: bool = true
	for entry: String in wanted:
		if not entry.begins_with("!"):
			chosen = false
	for entry: String in wanted:
		var pattern: String = entry.trim_prefix("!")
		if file.match(pattern) or (file + "." + method).match(pattern):
			if entry.begins_with("!"):
				return false
			chosen = true
	return chosen


func _initialize() -> void:
	_run.call_deferred()


func _run() -> void:
	OS.add_logger(_log)
	var wanted: PackedStringArray = OS.get_cmdline_user_args()
	var passed: int = 0
	var failed: int = 0
	var folder: String = "res://cases" if DirAccess.dir_exists_absolute("res://cases") else "res://tests/cases"
	var files: PackedStringArray = DirAccess.get_files_at(folder)
	files.sort()
	for file: String in files:
		if not file.begins_with("test_") or not file.ends_with(".gd"):
			continue
		var file_wanted: bool = wanted.is_empty()
		for entry: String in wanted:
			if entry.begins_with("!"):
				file_wanted = true  # only tests are left out, each by _is_wanted
				continue
			var pattern: bool = entry.contains("*") or entry.contains("?")
			file_wanted = file_wanted or pattern or entry == file.get_basename()
			file_wanted = file_wanted or entry.begins_with(file.get_basename() + ".")
		if not file_wanted:
			continue
		var script: GDScript = load(folder.path_join(file)) as GDScript
		if script == null or not script.can_instantiate():
			print("FAIL %s: the script does not load" % file)
			failed += 1
			continue
		for method: Dictionary in script.get_script_method_list():
			var name: String = method["name"]
			if not name.begins_with("test_"):
				continue
			if not _is_wanted(wanted, file.get_basename(), name):
				continue
			var case: TestCase = script.new() as TestCase
			case.tree = self
			case.log = _log
			_log.take()
			_log.take_warnings()
			var start: int = Time.get_ticks_msec()
			case.before_each()
			await case.call(name)
			case.after_each()
			case.restore_project_settings()
			await process_frame
			for error: String in _log.take():
				var allowed: bool = false
				for fragment: String in case.allowed_errors:
					allowed = allowed or error.contains(fragment)
				if not allowed:
					case.failures.append("unexpected engine error: " + error)
			var took: String = "(%.1f s)" % ((Time.get_ticks_msec() - start) / 1000.0)  # where the suite's time goes
			if case.failures.is_empty():
				passed += 1
				print("ok   %s.%s %s" % [file.get_basename(), name, took])
			else:
				failed += 1
				print("FAIL %s.%s %s" % [file.get_basename(), name, took])
				for failure: String in case.failures:
					print("     " + failure)
	print("godot: %d passed, %d failed" % [passed, failed])
	OS.remove_logger(_log)
	# Quitting while the renderer still compiles a pipeline in the background can deadlock the
	# engine's exit (godot#117064): a run of one fidelity test hung after its summary line in 3 of 5
	# runs (3 of 6 with three frames drawn first), and in none of 9 with this wait.
	await create_timer(EXIT_SETTLE_SECONDS).timeout
	quit(1 if failed > 0 or passed == 0 else 0)
