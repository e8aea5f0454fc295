extends TestCase
## The far levels against the full-mesh picture, as a player compares them. Fixed views of a
## 60 × 60 m field (14 400 plants) in calm air, drawn with automatic levels of detail, with every
## plant as mesh 1, and with the impostors alone on black (the region they cover): the SSIM and mean
## difference to the full-mesh picture and the impostor region's brightness relative to it. And slow
## walks (2 cm a frame) across switch distances: the largest local (16 × 16-pixel) change on frames
## where plants switched level against the largest on frames where none did (the pop ratio).
## Prints the figures; with FIDELITY_FULL=1 it measures every view and switch (tools/measure_lod.sh),
## otherwise the views and the switch that tell most, within the test command's time.

const NativeField: GDScript = preload("res://addons/sunflower_field/native/native_field.gd")
const Stage: GDScript = preload("res://runner/stage.gd")
const Picture: GDScript = preload("res://runner/picture.gd")
const Maps: GDScript = preload("res://runner/maps.gd")
const Dressing: GDScript = preload("res://runner/dressing.gd")
const FIELD_CELLS: int = 120  # 0.5 m cells: 60 × 60 m
## Eye and target of each view: head height inside, 5 m and 40 m outside, 25 m up at 45°, 60 m down.
const VIEWS: Dictionary = {
	"inside": [Vector3(30, 1.7, 45), Vector3(30, 1.4, 20)],
	"outside5": [Vector3(30, 1.7, 65), Vector3(30, 1.0, 30)],
	"outside40": [Vector3(30, 1.7, 100), Vector3(30, 1.0, 30)],
	"above45": [Vector3(30, 25, 55), Vector3(30, 0, 30)],
	"down60": [Vector3(30, 60, 30.01), Vector3(30, 0, 30)],
}
const QUICK_VIEWS: PackedStringArray = ["inside", "above45", "down60"]
## The switch distances walked across (the field's defaults: mesh 1 → 2 → 3 → sprite → billboard).
const QUICK_SWITCHES: Array[int] = [2]
## The walks' frames across a switch: 2 m in the full measurement, the middle metre in the test
## command. LOD passes come every 0.25 s (15 frames); the short walk holds two that switch plants,
## against 47 frames without, in half the time.
const WALK_FRAMES: int = 100
const QUICK_WALK_FRAMES: int = 50
## The first merged level's distance in the merge walk, the walk's frames (twice in the full
## measurement), where it starts (8 m up, 42 m south of the field) and where it looks (the ground
## 45 m ahead, 3 m into the field).
const MERGE_DISTANCE: float = 50.0
const MERGE_WALK_FRAMES: int = 20
const MERGE_EYE: Vector3 = Vector3(30.0, 8.0, 102.0)
const MERGE_LOOK: Vector3 = Vector3(0.0, -8.0, -45.0)
const STEP: float = 0.02

var stage: RefCounted
var field: SunflowerField
var camera: Camera3D
var picture: RefCounted
var full: bool = OS.get_environment("FIDELITY_FULL") == "1"
var window_size: Vector2i


func before_each() -> void:
	stage = Stage.new(tree.root, 400.0, Vector3(30.0, 0.0, 30.0))
	field = SunflowerField.new()
	stage.root.add_child(field)
	field.map = Maps.filled(FIELD_CELLS, FIELD_CELLS, "user://fidelity.field")
	field.wind_power = 0.0
	field.finish_build()
	field.set_process(false)  # the test advances it, a 60th of a second a frame
	camera = Camera3D.new()
	stage.root.add_child(camera)
	camera.make_current()
	window_size = tree.root.size
	var size: Vector2i = tree.root.get_viewport().get_visible_rect().size
	picture = Picture.new(size.x, size.y)


func after_each() -> void:
	tree.root.size = window_size  # whatever a test resized
	stage.root.free()


func test_far_levels_look_like_the_full_mesh_picture() -> void:
	var figures: Dictionary = {}
	for view: String in VIEWS if full else QUICK_VIEWS:
		var eye: Vector3 = VIEWS[view][0]
		var target: Vector3 = VIEWS[view][1]
		var auto: PackedFloat32Array = await _render(eye, target, -1, view + ".auto")
		var mesh_1: PackedFloat32Array = await _render(eye, target, 0, view + ".mesh1")
		var inside: PackedByteArray = picture.region(await _impostors_alone(eye, target, view + ".mask"))
		var share: float = float(inside.count(1)) / inside.size()
		var brightness: float = picture.mean_in(auto, inside) / picture.mean_in(mesh_1, inside)
		figures[view] = [picture.ssim(auto, mesh_1), picture.mean_difference(auto, mesh_1), share, brightness]
		print(
			(
				"     %s: SSIM to mesh 1 %.3f, mean difference %.4f, impostor region %.1f %%, its brightness %s"
				% [view, figures[view][0], figures[view][1], 100.0 * share, "%.3f" % brightness if share > 0 else "—"]
			)
		)
		if full and view in ["above45", "down60"]:
			await _print_pixel_noise(eye, target, mesh_1, view)
	if full:
		await _check_anti_aliased()
	# The targets: SSIM ≥ 0.99 at head height, ≥ 0.85 from above (met anti-aliased in both views,
	# _check_anti_aliased; at one sample a pixel straight down but not at 45°, docs/fidelity.md: mesh 3,
	# a model of a quarter of the triangles, reaches 0.915 and 0.963 there, so what is left is the
	# impostor's look, not the plants' places; reading the footprint's mip, or each view at one shared
	# place instead of where the pixel's point lies in it, scores lower), brightness within ±5 %.
	# What is checked is what this code reaches, so that a regression fails.
	check(figures["inside"][0] >= 0.99, "at head height the picture is the full-mesh one (%.3f)" % figures["inside"][0])
	check(figures["above45"][0] >= 0.72, "25 m up at 45°: SSIM %.3f, at least 0.72" % figures["above45"][0])
	check(figures["down60"][0] >= 0.86, "60 m straight down: SSIM %.3f, at least 0.86" % figures["down60"][0])
	for view: String in ["above45", "down60"]:
		check(
			absf(figures[view][3] - 1.0) <= 0.05,
			"%s: the impostors' brightness %.3f of the meshes', within ±5 %%" % [view, figures[view][3]]
		)


## The aerial views anti-aliased: drawn with the window 4 times as wide and high (16 samples a
## pixel) and box-filtered back to its size, automatic LOD against every plant as mesh 1. This is
## where 0.85 from above is met (0.870 at 45°, 0.931 straight down, docs/fidelity.md); at one
## sample a pixel the meshes' own aliasing bounds what any impostor can score (see below).
func _check_anti_aliased() -> void:
	var large: Vector2i = await _enlarge_window(4)
	for view: String in ["above45", "down60"]:
		var eye: Vector3 = VIEWS[view][0]
		var target: Vector3 = VIEWS[view][1]
		var auto: Image = await _render_image(eye, target, -1, view + "_x4.auto")
		var mesh_1: Image = await _render_image(eye, target, 0, view + "_x4.mesh1")
		var figure: float = _ssim_anti_aliased(auto, mesh_1, 2)
		print(
			"     %s anti-aliased (%d × %d box-filtered 4 × 4): SSIM to mesh 1 %.3f" % [view, large.x, large.y, figure]
		)
		check(figure >= 0.85, "%s anti-aliased: SSIM %.3f, at least 0.85" % [view, figure])


## What SSIM at one sample a pixel makes of two equally right pictures: the full-mesh picture
## against itself with the camera moved a quarter and half a pixel sideways (at the target's
## distance). An impostor cannot keep the meshes' aliasing to the pixel; a figure near these is as
## close as the meshes stay to themselves after a step of a few centimetres (0.780 and 0.632 at
## 45°, 0.826 and 0.763 straight down, docs/fidelity.md).
func _print_pixel_noise(eye: Vector3, target: Vector3, mesh_1: PackedFloat32Array, view: String) -> void:
	var pixel: float = 2.0 * tan(deg_to_rad(0.5 * camera.fov)) / picture.height * eye.distance_to(target)
	var figures: PackedStringArray = []
	for share: float in [0.25, 0.5]:
		camera.h_offset = share * pixel
		var moved: PackedFloat32Array = await _render(eye, target, 0, "%s.mesh1_moved%d" % [view, roundi(100 * share)])
		figures.append("%.3f moved %.2f of a pixel" % [picture.ssim(moved, mesh_1), share])
	camera.h_offset = 0.0
	print("     %s: mesh 1 against itself %s (%.3f m a pixel)" % [view, ", ".join(figures), pixel])


## From 150 m the field is a few pixels tall and each plant a few pixels wide: the impostors must
## cover about what the meshes cover (an alpha test at a fixed threshold lost such plants
## altogether: the field vanished, coverage 0.00), in about their colour (read from the coarse mips,
## which average a plant's head with the leaves the heads in front hide in a field, the field was
## olive where the meshes' is yellow: brightness 0.45).
func test_the_far_field_keeps_its_cover() -> void:
	var eye: Vector3 = Vector3(30, 50, 180)
	var target: Vector3 = Vector3(30, 0, 30)
	var meshes: PackedFloat32Array = await _field_alone(eye, target, 0, "far150.mesh1_alone")
	var impostors: PackedFloat32Array = await _field_alone(eye, target, -1, "far150.auto_alone")
	var meshes_in: PackedByteArray = picture.region(meshes)
	var impostors_in: PackedByteArray = picture.region(impostors)
	var cover: float = float(impostors_in.count(1)) / maxf(meshes_in.count(1), 1.0)
	var brightness: float = picture.mean_in(impostors, impostors_in) / picture.mean_in(meshes, meshes_in)
	print(
		(
			"     150 m away: the impostors cover %d pixels, the meshes %d: %.2f; their brightness %.3f of the meshes'"
			% [impostors_in.count(1), meshes_in.count(1), cover, brightness]
		)
	)
	check(meshes_in.count(1) > 1000, "the field is in view (%d pixels)" % meshes_in.count(1))
	check(cover >= 0.8 and cover <= 1.2, "the impostors cover %.2f of what the meshes cover, within 0.8–1.2" % cover)
	check(brightness >= 0.88, "the far impostors' brightness %.3f of the meshes', at least 0.88" % brightness)


## The 45° view at 1 280 × 720 (the window resized): a plant 20–35 m away then samples a mip one
## level finer than at 640 × 360. While the far reads' thresholds were plain mip levels, those
## plants were read unsharpened there, a darker ring: the impostors' brightness 0.942 of the meshes'.
## And the plants seen from 50–55° above, midway between two rows of views: while their blend was
## alpha-tested as one, they were drawn with the intersection of the views' outlines, a darker band
## (0.93 of the meshes' brightness).
func test_far_levels_keep_their_brightness_at_twice_the_resolution() -> void:
	var large: Vector2i = await _enlarge_window(2)
	picture = Picture.new(large.x, large.y)
	var eye: Vector3 = VIEWS["above45"][0]
	var target: Vector3 = VIEWS["above45"][1]
	var auto_image: Image = await _render_image(eye, target, -1, "above45_x2.auto")
	var mesh_1_image: Image = await _render_image(eye, target, 0, "above45_x2.mesh1")
	var auto: PackedFloat32Array = picture.luminance(auto_image)
	var mesh_1: PackedFloat32Array = picture.luminance(mesh_1_image)
	var inside: PackedByteArray = picture.region(await _impostors_alone(eye, target, "above45_x2.mask"))
	var brightness: float = picture.mean_in(auto, inside) / picture.mean_in(mesh_1, inside)
	var anti_aliased: float = _ssim_anti_aliased(auto_image, mesh_1_image, 1)
	print(
		(
			"     25 m up at 45°, %d × %d: the impostors' brightness %.3f of the meshes'; SSIM %.3f, box-filtered 2 × 2 %.3f"
			% [large.x, large.y, brightness, picture.ssim(auto, mesh_1), anti_aliased]
		)
	)
	# Two samples a pixel each way: 0.826 when last measured; 0.85 is reached with four (FIDELITY_FULL).
	check(anti_aliased >= 0.80, "anti-aliased (2 × 2 samples a pixel): SSIM %.3f, at least 0.80" % anti_aliased)
	check(inside.count(1) > 40000, "the impostors are in view (%d pixels)" % inside.count(1))
	check(absf(brightness - 1.0) <= 0.05, "the impostors' brightness %.3f of the meshes', within ±5 %%" % brightness)
	var midway: PackedByteArray = _seen_from(inside, large, 50.0, 55.0)
	var band: float = picture.mean_in(auto, midway) / picture.mean_in(mesh_1, midway)
	print("     seen from 50–55° above (%d pixels): %.3f" % [midway.count(1), band])
	check(midway.count(1) > 20000, "plants seen from 50–55° above are in view (%d pixels)" % midway.count(1))
	check(band >= 0.95, "those seen from 50–55° above: brightness %.3f of the meshes', at least 0.95" % band)


## Makes the window [param factor] times as wide and high (after_each sizes it back) and returns the
## size it draws, checked to be that.
func _enlarge_window(factor: int) -> Vector2i:
	tree.root.size = window_size * factor
	await RenderingServer.frame_post_draw
	var large: Vector2i = tree.root.get_visible_rect().size
	check(large == window_size * factor, "the window is %d times as large (%s)" % [factor, large])
	return large


## The SSIM of [param a] and [param b] after [param halvings] halvings of each (2 × 2 pixels
## averaged each time): pictures rendered 2^halvings times as wide and high, compared anti-aliased
## as supersampling draws them.
func _ssim_anti_aliased(a: Image, b: Image, halvings: int) -> float:
	var small_a: Image = a.duplicate() as Image
	var small_b: Image = b.duplicate() as Image
	for i: int in halvings:
		small_a.shrink_x2()
		small_b.shrink_x2()
	var small: RefCounted = Picture.new(small_a.get_width(), small_a.get_height())
	return small.ssim(small.luminance(small_a), small.luminance(small_b))


## The pixels of [param inside] (a picture of [param size]) that the camera sees from
## [param lowest]–[param highest] degrees above the horizontal.
func _seen_from(inside: PackedByteArray, size: Vector2i, lowest: float, highest: float) -> PackedByteArray:
	var seen: PackedByteArray = []
	seen.resize(inside.size())
	for y: int in size.y:
		for x: int in size.x:
			var i: int = y * size.x + x
			if inside[i] == 0:
				continue
			var elevation: float = rad_to_deg(-asin(camera.project_ray_normal(Vector2(x + 0.5, y + 0.5)).y))
			if elevation >= lowest and elevation < highest:
				seen[i] = 1
	return seen


## The field alone on black (no ground, no sky) drawn at [param force] (-1: automatic levels).
func _field_alone(eye: Vector3, target: Vector3, force: int, name: String) -> PackedFloat32Array:
	stage.show_scenery(false)
	var alone: PackedFloat32Array = await _render(eye, target, force, name)
	stage.show_scenery(true)
	return alone


func test_no_pops_where_plants_switch_level() -> void:
	var distances: PackedFloat32Array = field.lod_distances
	# Sprite and billboard draw the same impostor (one buffer per far chunk), so the last distance is
	# no switch on screen: the walks cross the three where the representation changes.
	for switch: int in range(3) if full else QUICK_SWITCHES:
		var changes: Array[PackedFloat32Array] = await _walk_across(distances[switch])
		var at_switches: float = _largest(changes[0])
		var elsewhere: float = _largest(changes[1])
		var ratio: float = at_switches / maxf(elsewhere, 1e-6)
		print(
			(
				"     switch at %.0f m: largest 16 × 16 change %.4f on %d frames with switches, %.4f on %d without: ratio %.2f"
				% [distances[switch], at_switches, changes[0].size(), elsewhere, changes[1].size(), ratio]
			)
		)
		check(changes[0].size() > 0 and changes[1].size() > 0, "frames of both kinds at %.0f m" % distances[switch])
		check(ratio <= 1.3, "no pop at the %.0f m switch: ratio %.2f, at most 1.3" % [distances[switch], ratio])


## Far tiles merge plant by plant: walking towards the band where the first merged level begins, no
## frame changes more than on the same walk with tiles that never merge. The merge distance is made
## 50 m, within the field (the default 200 m is where a plant is a few pixels), with 4 m chunks (32 m
## tiles), and the view is a telephoto one (12°) from 8 m up onto that band, so the plants are drawn
## four times larger than a player at head height would see them.
func test_no_pops_where_far_tiles_merge() -> void:
	var frames: int = MERGE_WALK_FRAMES * (2 if full else 1)
	var merged: Array[PackedFloat32Array] = await _walk_onto_merge(MERGE_DISTANCE, frames)
	var fade: float = NativeField.new(field.get_simulation()).choose_tile_level(MERGE_LOOK.length()).y
	var never: Array[PackedFloat32Array] = await _walk_onto_merge(0.0, frames)
	var ratio: float = _largest(merged[0]) / maxf(_largest(never[0]), 1e-6)
	print(
		(
			"     merge at %.0f m: largest 16 × 16 change %.4f over %d frames, %.4f with tiles that never merge: ratio %.2f"
			% [MERGE_DISTANCE, _largest(merged[0]), merged[0].size(), _largest(never[0]), ratio]
		)
	)
	check(fade > 0.0 and fade < 1.0, "the walk looks into the fade to the first merged level (%.2f)" % fade)
	var apart: float = picture.mean_difference(merged[1], never[1])
	check(apart > 0.01, "merged tiles are drawn: the walks' first pictures differ by %.4f" % apart)
	check(ratio <= 1.3, "no pop where far tiles merge: ratio %.2f, at most 1.3" % ratio)


## Walks 2 cm a frame from MERGE_EYE towards the field, looking down along MERGE_LOOK,
## with 4 m chunks and [param merge] as the tile merge distance; the largest 16 × 16 change of each
## frame (first) and the first picture (second).
func _walk_onto_merge(merge: float, frames: int) -> Array[PackedFloat32Array]:
	field.chunk_size = 4.0
	field.tile_merge_distance = merge
	field.finish_build()
	camera.fov = 12.0
	var changes: PackedFloat32Array = []
	var first: PackedFloat32Array = []
	var before: PackedFloat32Array = []
	for frame: int in frames:
		var eye: Vector3 = MERGE_EYE + Vector3(0.0, 0.0, -frame * STEP)
		var name: String = "merge_walk_%s" % ("merged" if merge > 0.0 else "never") if frame == 0 else ""
		var now: PackedFloat32Array = await _render(eye, eye + MERGE_LOOK, -1, name, 10 if frame == 0 else 1)
		if frame == 0:
			first = now
		else:
			changes.append(picture.largest_block_change(before, now))
		before = now
	return [changes, first]


## Walks towards the field's south edge at head height, 2 cm a frame, so that its nearest plants
## cross [param distance] halfway; the largest 16 × 16 change of each frame, on frames where plants
## switched level (first) and where none did (second).
func _walk_across(distance: float) -> Array[PackedFloat32Array]:
	var edge: float = FIELD_CELLS * 0.5
	var at_switches: PackedFloat32Array = []
	var elsewhere: PackedFloat32Array = []
	var before: PackedFloat32Array = []
	var counts: PackedInt32Array = []
	var frames: int = WALK_FRAMES if full else QUICK_WALK_FRAMES
	for frame: int in frames:
		var z: float = edge + distance + (frames * 0.5 - frame) * STEP
		var now: PackedFloat32Array = await _render(Vector3(30.0, 1.7, z), Vector3(30.0, 1.0, z - 20.0), -1, "", 1)
		var now_counts: PackedInt32Array = field.get_lod_counts()
		if frame > 0:
			var change: float = picture.largest_block_change(before, now)
			if now_counts != counts:
				at_switches.append(change)
			else:
				elsewhere.append(change)
		before = now
		counts = now_counts
	return [at_switches, elsewhere]


## The picture from [param eye] towards [param target] with [param force] (-1: automatic LOD),
## after [param updates] updates of a 60th of a second; saved to the artifacts as [param name].
func _render(eye: Vector3, target: Vector3, force: int, name: String, updates: int = 10) -> PackedFloat32Array:
	return picture.luminance(await _render_image(eye, target, force, name, updates))


## The picture of [method _render] as an image, at the window's size.
func _render_image(eye: Vector3, target: Vector3, force: int, name: String, updates: int = 10) -> Image:
	camera.look_at_from_position(eye, target)
	field.force_lod = force
	for i: int in updates:  # a jump turns chunks active a budget's worth per update
		field.advance(1.0 / 60.0)
	# One frame is enough: a second one drew the same picture to the byte in every view (session
	# 20), and a frame of 14 400 mesh-1 plants takes 26 s under software rendering.
	await RenderingServer.frame_post_draw
	var image: Image = tree.root.get_viewport().get_texture().get_image()
	if not name.is_empty():
		image.save_png(artifact_path("fidelity/%s.png" % name))
	return image


## The view with every mesh part black and unshaded, no ground and a black sky: what is not black
## is impostor.
func _impostors_alone(eye: Vector3, target: Vector3, name: String) -> PackedFloat32Array:
	var black: StandardMaterial3D = Dressing.unlit_black()
	Dressing.dress_parts(field, func(_level: int, _part: int) -> Material: return black)
	var mask: PackedFloat32Array = await _field_alone(eye, target, -1, name)
	field.plant = null  # the built-in sunflower again
	return mask


static func _largest(values: PackedFloat32Array) -> float:
	var largest: float = 0.0
	for value: float in values:
		largest = maxf(largest, value)
	return largest
