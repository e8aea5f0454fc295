extends RefCounted
## Picture metrics for comparing renders: luminance, structural similarity (SSIM), the largest
## local change between two frames, and a region's mean brightness. Pictures are luminance arrays
## (Rec. 709 weights on the sRGB values, 0–1) of one width and height.

## SSIM's constants (K1 = 0.01, K2 = 0.03 for a range of 1) and its window, pixels.
const C1: float = 0.0001
const C2: float = 0.0009
const WINDOW: int = 7

var width: int
var height: int


func _init(picture_width: int, picture_height: int) -> void:
	width = picture_width
	height = picture_height


## The luminance of every pixel of [param image], row by row.
func luminance(image: Image) -> PackedFloat32Array:
	var bytes: PackedByteArray = _rgb_bytes(image)
	var out: PackedFloat32Array = PackedFloat32Array()
	out.resize(width * height)
	for i: int in out.size():
		out[i] = ((0.2126 * bytes[3 * i] + 0.7152 * bytes[3 * i + 1] + 0.0722 * bytes[3 * i + 2]) / 255.0)
	return out


## The mean structural similarity of [param a] and [param b] over every 7 × 7 window.
func ssim(a: PackedFloat32Array, b: PackedFloat32Array) -> float:
	var aa: PackedFloat32Array = PackedFloat32Array()
	var bb: PackedFloat32Array = PackedFloat32Array()
	var ab: PackedFloat32Array = PackedFloat32Array()
	aa.resize(a.size())
	bb.resize(a.size())
	ab.resize(a.size())
	for i: int in a.size():
		aa[i] = a[i] * a[i]
		bb[i] = b[i] * b[i]
		ab[i] = a[i] * b[i]
	var sum_a: PackedFloat64Array = _integral(a)
	var sum_b: PackedFloat64Array = _integral(b)
	var sum_aa: PackedFloat64Array = _integral(aa)
	var sum_bb: PackedFloat64Array = _integral(bb)
	var sum_ab: PackedFloat64Array = _integral(ab)
	var n: float = WINDOW * WINDOW
	var total: float = 0.0
	var windows: int = 0
	var stride: int = width + 1
	for y: int in height - WINDOW + 1:
		# A window's sum is the integral at its four corners: bottom right - top right - bottom left
		# + top left (written out here: a call per sum took most of the time).
		for x: int in width - WINDOW + 1:
			var top_left: int = y * stride + x
			var bottom_left: int = top_left + WINDOW * stride
			var top_right: int = top_left + WINDOW
			var bottom_right: int = bottom_left + WINDOW
			var mean_a: float = (sum_a[bottom_right] - sum_a[top_right] - sum_a[bottom_left] + sum_a[top_left]) / n
			var mean_b: float = (sum_b[bottom_right] - sum_b[top_right] - sum_b[bottom_left] + sum_b[top_left]) / n
			var var_a: float = (
				(sum_aa[bottom_right] - sum_aa[top_right] - sum_aa[bottom_left] + sum_aa[top_left]) / n
				- mean_a * mean_a
			)
			var var_b: float = (
				(sum_bb[bottom_right] - sum_bb[top_right] - sum_bb[bottom_left] + sum_bb[top_left]) / n
				- mean_b * mean_b
			)
			var covariance: float = (
				(sum_ab[bottom_right] - sum_ab[top_right] - sum_ab[bottom_left] + sum_ab[top_left]) / n
				- mean_a * mean_b
			)
			total += (
				((2.0 * mean_a * mean_b + C1) * (2.0 * covariance + C2))
				/ ((mean_a * mean_a + mean_b * mean_b + C1) * (var_a + var_b + C2))
			)
			windows += 1
	return total / maxf(windows, 1.0)


## The mean absolute difference of two pictures.
func mean_difference(a: PackedFloat32Array, b: PackedFloat32Array) -> float:
	var sum: float = 0.0
	for i: int in a.size():
		sum += absf(a[i] - b[i])
	return sum / maxf(a.size(), 1.0)


## The largest mean absolute change over any [param block] × [param block] tile between two frames.
func largest_block_change(a: PackedFloat32Array, b: PackedFloat32Array, block: int = 16) -> float:
	var largest: float = 0.0
	for y0: int in range(0, height - block + 1, block):
		for x0: int in range(0, width - block + 1, block):
			var sum: float = 0.0
			for y: int in range(y0, y0 + block):
				var row: int = y * width
				for x: int in range(x0, x0 + block):
					sum += absf(a[row + x] - b[row + x])
			largest = maxf(largest, sum / (block * block))
	return largest


## 1 where a pixel of [param image] is leaf green (green above both red and blue by more than
## 8 of 255), else 0: with [method mean_in], the share of a region that is leaves.
func leaf_green(image: Image) -> PackedFloat32Array:
	var bytes: PackedByteArray = _rgb_bytes(image)
	var out: PackedFloat32Array = PackedFloat32Array()
	out.resize(width * height)
	for i: int in out.size():
		var green: int = bytes[3 * i + 1]
		out[i] = 1.0 if green > bytes[3 * i] + 8 and green > bytes[3 * i + 2] + 8 else 0.0
	return out


## The pixels of [param mask] brighter than 0.02 (a picture of the region on black).
func region(mask: PackedFloat32Array) -> PackedByteArray:
	var out: PackedByteArray = PackedByteArray()
	out.resize(mask.size())
	for i: int in mask.size():
		out[i] = 1 if mask[i] > 0.02 else 0
	return out


## [param inside] (a region) grown by [param by] pixels each way: with the gaps between a sparse
## crown's leaves, so that two pictures are compared over the same pixels whichever of them covers
## each (a region that one picture's plants alone make holds none of the other's sky between them).
func grown(inside: PackedByteArray, by: int) -> PackedByteArray:
	var values: PackedFloat32Array = PackedFloat32Array()
	values.resize(inside.size())
	for i: int in inside.size():
		values[i] = inside[i]
	var integral: PackedFloat64Array = _integral(values)
	var stride: int = width + 1
	var out: PackedByteArray = PackedByteArray()
	out.resize(inside.size())
	for y: int in height:
		var top: int = maxi(y - by, 0) * stride
		var bottom: int = mini(y + by + 1, height) * stride
		for x: int in width:
			var left: int = maxi(x - by, 0)
			var right: int = mini(x + by + 1, width)
			var sum: float = (
				integral[bottom + right] - integral[top + right] - integral[bottom + left] + integral[top + left]
			)
			out[y * width + x] = 1 if sum > 0.5 else 0
	return out


## The mean luminance of [param ours] over [param inside] (a region) against [param theirs]'.
func brightness_of(ours: Image, theirs: Image, inside: PackedByteArray) -> float:
	return mean_in(luminance(ours), inside) / mean_in(luminance(theirs), inside)


## The mean of [param picture] over [param inside] (a region); NAN when it is empty.
func mean_in(picture: PackedFloat32Array, inside: PackedByteArray) -> float:
	var sum: float = 0.0
	var count: int = 0
	for i: int in picture.size():
		if inside[i]:
			sum += picture[i]
			count += 1
	return sum / count if count > 0 else NAN


## The mean luminance of [param image] and the mean standard deviation of its luminance within
## blocks of [param block] × [param block] pixels (its contrast at that scale: dappled shade's).
static func shade(image: Image, block: int) -> Vector2:
	var size: Vector2i = image.get_size()
	var bytes: PackedByteArray = _rgb_bytes(image)
	var blocks: Vector2i = size / block
	var n: float = block * block
	var total: float = 0.0
	var spread: float = 0.0
	for by: int in blocks.y:
		for bx: int in blocks.x:
			var sum: float = 0.0
			var squares: float = 0.0
			for y: int in range(by * block, (by + 1) * block):
				for x: int in range(bx * block, (bx + 1) * block):
					var i: int = 3 * (y * size.x + x)
					var value: float = (0.2126 * bytes[i] + 0.7152 * bytes[i + 1] + 0.0722 * bytes[i + 2]) / 255.0
					sum += value
					squares += value * value
			total += sum
			spread += sqrt(maxf(squares / n - (sum / n) * (sum / n), 0.0))
	return Vector2(total / (blocks.x * blocks.y * n), spread / (blocks.x * blocks.y))


## [param image]'s pixels as 8-bit red, green and blue, row by row (the image itself unchanged).
static func _rgb_bytes(image: Image) -> PackedByteArray:
	var rgb: Image = image.duplicate() as Image
	rgb.convert(Image.FORMAT_RGB8)
	return rgb.get_data()


func _integral(values: PackedFloat32Array) -> PackedFloat64Array:
	var stride: int = width + 1
	var out: PackedFloat64Array = PackedFloat64Array()
	out.resize(stride * (height + 1))
	for y: int in height:
		var row: float = 0.0
		var source: int = y * width
		var above: int = y * stride + 1
		for x: int in width:
			row += values[source + x]
			out[above + stride + x] = out[above + x] + row
	return out


## The pixels of [param image] that are not black (covered), of those the leaf green ones, and the
## light of all its pixels (the sum of their luminance, 0–1 each, as stored).
static func covered_green_light(image: Image) -> Vector3:
	var bytes: PackedByteArray = _rgb_bytes(image)
	var covered: int = 0
	var green: int = 0
	var light: float = 0.0
	for i: int in range(0, bytes.size(), 3):
		light += 0.2126 * bytes[i] + 0.7152 * bytes[i + 1] + 0.0722 * bytes[i + 2]
		if bytes[i] + bytes[i + 1] + bytes[i + 2] > 12:
			covered += 1
			if bytes[i + 1] > bytes[i] + 8 and bytes[i + 1] > bytes[i + 2] + 8:
				green += 1
	return Vector3(covered, green, light / 255.0)
