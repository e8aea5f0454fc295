@tool
@icon("icons/sunflower_wind.svg")
class_name SunflowerWind
extends Resource
## Steady wind that makes sunflowers sway: the thesis' "data format for the phenomena that
## animate the plants". Share one resource between fields to give them the same weather.
##
## The sway follows the thesis (J. Plas, 2008, equations 4–6): each plant has a phase φ that
## advances at [code]b·π·p_w[/code] (or [code]b·π·(p_w/20 + 1)[/code] above 1), where [code]b[/code]
## is ±1 and is redrawn every [member flip_interval] seconds; the bend [code]p = p_w·h·sin φ[/code]
## tilts the bottom part by [code]p/d2[/code] and the middle by [code]p/d1[/code]; the head rides
## on the middle. A share of the sway travels downwind as a gust.

## Wind power p_w: 0 is calm, 1.0 ≈ 1 m/s, at most 100.
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var power: float = 1.0:
	set(value):
		if not is_finite(value):
			push_warning("SunflowerWind.power: %s is not a finite number; using 0" % value)
			value = 0.0
		elif value < 0.0 or value > 100.0:
			push_warning("SunflowerWind.power: %s is outside 0–100; using %s" % [value, clampf(value, 0.0, 100.0)])
			value = clampf(value, 0.0, 100.0)
		if value != power:
			power = value
			emit_changed()
## Where the wind blows to, on the ground plane (x, z). A zero vector means +x.
@export var direction: Vector2 = Vector2(1.0, 0.0):
	set(value):
		if not value.is_finite() or value.is_zero_approx():
			push_warning("SunflowerWind.direction: %s has no direction; using (1, 0)" % value)
			value = Vector2(1.0, 0.0)
		if value != direction:
			direction = value
			emit_changed()
## What one press of the demo's wind keys adds to or subtracts from [member power].
@export_range(0.0, 100.0, 0.1, "suffix:m/s") var increment: float = 0.1:
	set(value):
		increment = clampf(value, 0.0, 100.0) if is_finite(value) else 0.1
		emit_changed()

@export_group("Dynamics")
## Stiffness of the middle part (thesis d1 = 1.5): the middle tilts by p/d1.
@export_range(0.1, 20.0, 0.01) var stiffness_middle: float = 1.5:
	set(value):
		stiffness_middle = maxf(value, 0.1) if is_finite(value) else 1.5
		emit_changed()
## Stiffness of the bottom part (thesis d2 = 3): the bottom tilts by p/d2.
@export_range(0.1, 20.0, 0.01) var stiffness_bottom: float = 3.0:
	set(value):
		stiffness_bottom = maxf(value, 0.1) if is_finite(value) else 3.0
		emit_changed()
## Bend per unit of power (thesis h = π/12 = 15°).
@export_range(0.0, 90.0, 0.1, "radians_as_degrees") var bend_per_power: float = PI / 12.0:
	set(value):
		bend_per_power = value if is_finite(value) else PI / 12.0
		emit_changed()
## Limit on the summed tilt of bottom and middle, so strong winds do not fold plants over.
@export_range(0.0, 90.0, 0.1, "radians_as_degrees") var max_bend: float = PI / 4.0:
	set(value):
		max_bend = clampf(value, 0.0, PI) if is_finite(value) else PI / 4.0
		emit_changed()
## Seconds between redraws of each plant's sway direction (thesis: 2 s), staggered per plant.
@export_range(0.05, 30.0, 0.05, "suffix:s") var flip_interval: float = 2.0:
	set(value):
		flip_interval = maxf(value, 0.05) if is_finite(value) else 2.0
		emit_changed()
## Chance that a redraw reverses the sway direction (thesis: 50 %).
@export_range(0.0, 1.0, 0.01) var flip_chance: float = 0.5:
	set(value):
		flip_chance = clampf(value, 0.0, 1.0) if is_finite(value) else 0.5
		emit_changed()
## Speed at which a bend is handed on downwind to the neighbours; 0 turns the gust off.
@export_range(0.0, 50.0, 0.1, "suffix:m/s") var gust_speed: float = 3.0:
	set(value):
		gust_speed = maxf(value, 0.0) if is_finite(value) else 3.0
		emit_changed()
## How much of the sway is the travelling gust (0: every plant on its own, 1: only the gust).
@export_range(0.0, 1.0, 0.01) var gust_share: float = 0.5:
	set(value):
		gust_share = clampf(value, 0.0, 1.0) if is_finite(value) else 0.5
		emit_changed()


## The dynamics as the native core takes them.
func get_dynamics() -> PackedFloat32Array:
	return PackedFloat32Array(
		[
			stiffness_middle,
			stiffness_bottom,
			bend_per_power,
			max_bend,
			flip_interval,
			flip_chance,
			gust_speed,
			gust_share,
		]
	)
