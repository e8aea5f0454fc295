@tool
@icon("icons/sunflower_wind.svg")
class_name SunflowerWind
extends Resource
## Steady wind that makes sunflowers sway: the thesis' "data format for the phenomena that
## animate the plants". Share one resource between fields to give them the same weather.
##
## Two models ([member model]). [b]Natural[/b] (the default, for games): plants lean downwind by a
## mean that grows with [member power] and saturates smoothly (never pinned at [member max_bend]),
## sway about it, and gusts of varying strength roll across the field at the wind's speed; changes
## of power and direction ease in over half a second. [b]Thesis[/b] reproduces J. Plas (2008),
## equations 4–6, exactly: each plant has a phase φ that advances at [code]b·π·p_w[/code] (or
## [code]b·π·(p_w/20 + 1)[/code] above 1), where [code]b[/code] is ±1 and is redrawn every
## [member flip_interval] seconds; the bend [code]p = p_w·h·sin φ[/code] swings about upright. In
## both the bottom part tilts by [code]p/d2[/code] and the middle by [code]p/d1[/code]; the head
## rides on the middle.

## The wind models.
enum Model { THESIS, NATURAL }

const Native: GDScript = preload("native/native.gd")

## [b]Natural[/b]: a downwind lean, sway and rolling gusts, for games. [b]Thesis[/b]: the thesis'
## equations exactly, swinging about upright (for reproducing it).
@export var model: Model = Model.NATURAL:
	set(value):
		value = Native.accept_int("SunflowerWind.model", value, model) as Model
		if value != model:
			model = value
			emit_changed()
## Wind power p_w: 0 is calm, 1.0 ≈ 1 m/s, at most 100.
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var power: float = 1.0:
	set(value):
		value = Native.accept("SunflowerWind.power", value, power)
		if value != power:
			power = value
			emit_changed()
## Where the wind blows to, on the ground plane (x, z). A zero vector means +x.
@export var direction: Vector2 = Vector2(1.0, 0.0):
	set(value):
		var used: Vector2 = Native.sanitize_wind_direction(value)
		if used != value:
			push_warning("SunflowerWind.direction: %s has no direction; using %s" % [value, used])
		if used != direction:
			direction = used
			emit_changed()
## What one press of the demo's wind keys adds to or subtracts from [member power].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var increment: float = 0.1:
	set(value):
		value = Native.accept("SunflowerWind.increment", value, increment)
		if value != increment:
			increment = value
			emit_changed()

@export_group("Dynamics")
## Stiffness of the middle part (thesis d1 = 1.5): the middle tilts by p/d1.
@export_range(0.1, 20.0, 0.01, "or_greater") var stiffness_middle: float = 1.5:
	set(value):
		value = Native.accept("SunflowerWind.stiffness_middle", value, stiffness_middle)
		if value != stiffness_middle:
			stiffness_middle = value
			emit_changed()
## Stiffness of the bottom part (thesis d2 = 3): the bottom tilts by p/d2.
@export_range(0.1, 20.0, 0.01, "or_greater") var stiffness_bottom: float = 3.0:
	set(value):
		value = Native.accept("SunflowerWind.stiffness_bottom", value, stiffness_bottom)
		if value != stiffness_bottom:
			stiffness_bottom = value
			emit_changed()
## Bend per unit of power (thesis h = π/12 = 15°).
@export_range(0.0, 90.0, 0.1, "radians_as_degrees") var bend_per_power: float = PI / 12.0:
	set(value):
		value = Native.accept("SunflowerWind.bend_per_power", value, bend_per_power)
		if value != bend_per_power:
			bend_per_power = value
			emit_changed()
## Limit on the summed tilt of bottom and middle, so strong winds do not fold plants over.
@export_range(0.0, 180.0, 0.1, "radians_as_degrees") var max_bend: float = PI / 4.0:
	set(value):
		value = Native.accept("SunflowerWind.max_bend", value, max_bend)
		if value != max_bend:
			max_bend = value
			emit_changed()
## Seconds between redraws of each plant's sway direction (thesis: 2 s), staggered per plant.
@export_range(0.05, 30.0, 0.05, "or_greater", "suffix:s") var flip_interval: float = 2.0:
	set(value):
		value = Native.accept("SunflowerWind.flip_interval", value, flip_interval)
		if value != flip_interval:
			flip_interval = value
			emit_changed()
## Chance that a redraw reverses the sway direction (thesis: 50 %).
@export_range(0.0, 1.0, 0.01) var flip_chance: float = 0.5:
	set(value):
		value = Native.accept("SunflowerWind.flip_chance", value, flip_chance)
		if value != flip_chance:
			flip_chance = value
			emit_changed()
## Thesis model: speed at which a bend is handed on downwind to the neighbours; 0 turns the gust
## off. (Natural gusts travel at the wind's own speed.)
@export_range(0.0, 50.0, 0.1, "or_greater", "suffix:m/s") var gust_speed: float = 3.0:
	set(value):
		value = Native.accept("SunflowerWind.gust_speed", value, gust_speed)
		if value != gust_speed:
			gust_speed = value
			emit_changed()
## How much of the motion is the travelling gust (0: every plant on its own, 1: only the gust).
@export_range(0.0, 1.0, 0.01) var gust_share: float = 0.5:
	set(value):
		value = Native.accept("SunflowerWind.gust_share", value, gust_share)
		if value != gust_share:
			gust_share = value
			emit_changed()
## Natural wind: the seconds a change of [member power] or [member direction] takes to ease in,
## at a steady rate (0: at once). A storm that builds over ten seconds: 10.
@export_range(0.0, 60.0, 0.1, "or_greater", "suffix:s") var ease_time: float = 0.5:
	set(value):
		value = Native.accept("SunflowerWind.ease_time", value, ease_time)
		if value != ease_time:
			ease_time = value
			emit_changed()


## Whether every setting is its default (a field does not save a wind nobody changed).
func is_default() -> bool:
	var fresh: SunflowerWind = SunflowerWind.new()
	for property: Dictionary in get_property_list():
		if property["usage"] & PROPERTY_USAGE_STORAGE and property["usage"] & PROPERTY_USAGE_SCRIPT_VARIABLE:
			if get(property["name"]) != fresh.get(property["name"]):
				return false
	return true


## The inspector's range hints take their limits from the core's table (native.gd: [code]range_hint[/code]).
func _validate_property(property: Dictionary) -> void:
	if property["hint"] == PROPERTY_HINT_RANGE:
		property["hint_string"] = Native.range_hint("SunflowerWind." + property["name"], property["hint_string"])
