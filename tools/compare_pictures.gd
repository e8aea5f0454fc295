extends SceneTree
## Compares two pictures as the tests do (tests/godot/runner/picture.gd): SSIM over 7 × 7 windows of
## their luminance, and the second's mean brightness over the first's. For measurements:
##   godot --headless --path tests/godot --script ../../tools/compare_pictures.gd -- A.png B.png

const Picture: GDScript = preload("res://runner/picture.gd")


func _init() -> void:
	var paths: PackedStringArray = OS.get_cmdline_user_args()
	if paths.size() != 2:
		printerr("compare_pictures: give two PNG files")
		quit(2)
		return
	var a: Image = Image.load_from_file(paths[0])
	var b: Image = Image.load_from_file(paths[1])
	if a == null or b == null or a.get_size() != b.get_size():
		printerr("compare_pictures: cannot read both, or their sizes differ")
		quit(1)
		return
	var picture: RefCounted = Picture.new(a.get_width(), a.get_height())
	var la: PackedFloat32Array = picture.luminance(a)
	var lb: PackedFloat32Array = picture.luminance(b)
	var mean_a: float = 0.0
	var mean_b: float = 0.0
	for i: int in la.size():
		mean_a += la[i]
		mean_b += lb[i]
	print("compare_pictures: SSIM %.4f, brightness %.4f×" % [picture.ssim(la, lb), mean_b / maxf(mean_a, 1e-6)])
	quit(0)
