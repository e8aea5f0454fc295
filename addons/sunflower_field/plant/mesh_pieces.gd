@tool
extends RefCounted
## A surface's pieces: the triangles joined by shared edges (or edges whose ends are at one place) — a
## leaf card, a blade, a twig. A plant's coarser mesh levels thin them, as the engines that draw forests
## do: a surface of foliage cards keeps a share of its cards, spread evenly over the plant, and
## the kept cards grow (fewer, bigger leaves; a coarser level keeps a subset of a finer level's cards,
## so no card comes back as the plant moves away); a surface of branches keeps its biggest pieces,
## dropping twigs. A card standing on the plant's base (a blade of grass) grows only in width, so that
## it keeps its foot on the ground and its height; any other grows about its centre. No card grows out
## of the bounds it is given.

## A piece of at most this many triangles is a card, and a surface whose pieces have at most this many
## on average is of cards (a Sapling maple's leaves are 4 each; so are a Sapling Japanese maple's,
## five to a stalk, touching at its end). Bigger pieces of a surface of cards (a trunk merged with its
## leaves) are kept as they are.
const CARD_TRIANGLES: float = 8.0
## The vertex arrays a plant's merged surfaces have (scene_plant.gd keeps these alone; a tangent is
## four numbers a vertex, any other one value).
const VERTEX_ARRAYS: Array[int] = [
	Mesh.ARRAY_VERTEX, Mesh.ARRAY_NORMAL, Mesh.ARRAY_TANGENT, Mesh.ARRAY_COLOR, Mesh.ARRAY_TEX_UV, Mesh.ARRAY_TEX_UV2
]
## Pieces whose areas are within a step of 2^(1 / this) of each other are of one size when a
## surface of branches keeps its biggest ([method biggest]).
const SIZE_CLASSES_AN_OCTAVE: float = 4.0
## A card whose lowest point is within this share of the bounds' height of their bottom stands on it.
const STANDING_SHARE: float = 0.02

## The surface's arrays, as given.
var arrays: Array
## How many pieces it has.
var count: int = 0
## The piece of each triangle (numbered in the order the pieces first appear).
var piece_of: PackedInt32Array = []
## Per piece: its area, its triangles, its area-weighted normal, the mean of its vertices, its lowest y.
var area: PackedFloat32Array = []
var triangles: PackedInt32Array = []
var normal: PackedVector3Array = []
var centre: PackedVector3Array = []
var lowest: PackedFloat32Array = []
## The pieces that are cards.
var cards: PackedInt32Array = []
var _order: Array[int] = []  # the cards in the order they are kept (_card_order)
var _biggest: Array[int] = []  # the pieces in the order biggest() keeps them (_biggest_order)


func _init(surface_arrays: Array) -> void:
	arrays = surface_arrays
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	# Triangles join where they share an edge: its two ends, by place (a surface's vertices split at
	# seams are at one place). Leaves that only touch at a point (a cluster on one stalk) stay apart.
	var place_of: PackedInt32Array = []  # a vertex -> the number of its place
	place_of.resize(positions.size())
	var places: Dictionary = {}  # a place -> its number
	for vertex: int in positions.size():
		place_of[vertex] = places.get(positions[vertex], places.size())
		places[positions[vertex]] = place_of[vertex]
	var parent: Array[int] = []
	parent.assign(range(indices.size() / 3))
	var edge_of: Dictionary = {}  # an edge (its ends' places) -> the first triangle along it
	for k: int in range(0, indices.size() - 2, 3):
		for corner: int in 3:
			var a: int = place_of[indices[k + corner]]
			var b: int = place_of[indices[k + (corner + 1) % 3]]
			var edge: int = mini(a, b) * places.size() + maxi(a, b)
			if edge_of.has(edge):
				_join(parent, edge_of[edge], k / 3)
			else:
				edge_of[edge] = k / 3
	var number: Dictionary = {}  # a piece's root triangle -> its number
	piece_of.resize(indices.size() / 3)
	for triangle: int in piece_of.size():
		var root: int = _root_of(parent, triangle)
		if not number.has(root):
			number[root] = number.size()
		piece_of[triangle] = number[root]
	count = number.size()
	area.resize(count)
	triangles.resize(count)
	normal.resize(count)
	centre.resize(count)
	lowest.resize(count)
	lowest.fill(INF)
	var corners: PackedInt32Array = []  # per piece: the vertices counted in its centre
	corners.resize(count)
	var first_piece: PackedInt32Array = []  # per vertex: the first piece it was counted for, or -1
	first_piece.resize(positions.size())
	first_piece.fill(-1)
	var also_counted: Dictionary = {}  # a vertex of more than one piece -> the others it was counted for
	for triangle: int in piece_of.size():
		var a: Vector3 = positions[indices[3 * triangle]]
		var across: Vector3 = (positions[indices[3 * triangle + 1]] - a).cross(positions[indices[3 * triangle + 2]] - a)
		var piece: int = piece_of[triangle]
		area[piece] += 0.5 * across.length()
		triangles[piece] += 1
		normal[piece] += across
		for corner: int in 3:
			var vertex: int = indices[3 * triangle + corner]
			if first_piece[vertex] == piece:
				continue
			if first_piece[vertex] < 0:
				first_piece[vertex] = piece
			elif also_counted.get(vertex, PackedInt32Array()).has(piece):
				continue
			else:
				also_counted[vertex] = also_counted.get(vertex, PackedInt32Array()) + PackedInt32Array([piece])
			centre[piece] += positions[vertex]
			corners[piece] += 1
			lowest[piece] = minf(lowest[piece], positions[vertex].y)
	for piece: int in count:
		centre[piece] /= maxi(corners[piece], 1)
		if is_card(piece):
			cards.append(piece)


## Whether the surface is of cards ([constant CARD_TRIANGLES]).
func are_cards() -> bool:
	return count > 0 and piece_of.size() <= CARD_TRIANGLES * count


## Whether [param piece] is a card ([constant CARD_TRIANGLES]).
func is_card(piece: int) -> bool:
	return triangles[piece] <= CARD_TRIANGLES


## How many cards [param share] of them is (at least one, when there are any).
func kept_count(share: float) -> int:
	return clampi(roundi(share * cards.size()), mini(1, cards.size()), cards.size())


## How much each card kept at [param share] grows in area for the kept ones to have the area of all.
func area_growth(share: float) -> float:
	var keeps: PackedByteArray = _chosen(kept_count(share))
	var kept_area: float = 0.0
	var all_area: float = 0.0
	for piece: int in cards:
		all_area += area[piece]
		kept_area += area[piece] if keeps[piece] else 0.0
	return all_area / kept_area if kept_area > 0.0 else 1.0


## The surface's cards thinned to [param share] of them, each kept one grown [param growth] times in
## area, no vertex past [param bounds] (the plant's; their bottom is its base), its other pieces as
## they are: new arrays holding only the vertices the kept pieces use.
func cards_thinned(share: float, growth: float, bounds: AABB) -> Array:
	var keeps: PackedByteArray = _chosen(kept_count(share))
	var picked: Dictionary = _picked_triangles(keeps)
	var used: PackedInt32Array = picked.used
	var positions: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var standing_below: float = bounds.position.y + STANDING_SHARE * bounds.size.y
	var grown: PackedVector3Array = []
	grown.resize(used.size())
	for k: int in used.size():
		var piece: int = (picked.piece_of_vertex as PackedInt32Array)[k]
		if not is_card(piece):
			grown[k] = positions[used[k]]
			continue
		var offset: Vector3 = positions[used[k]] - centre[piece]
		var across: Vector3 = normal[piece].cross(Vector3.UP).normalized()
		var moved: Vector3
		if lowest[piece] <= standing_below and across.is_normalized():
			moved = centre[piece] + offset + across * offset.dot(across) * (growth - 1.0)  # wider by the growth
		else:
			moved = centre[piece] + offset * sqrt(growth)  # each way by its root
		grown[k] = moved.clamp(bounds.position, bounds.end)
	var out: Array = _arrays_of(used, picked.indices)
	out[Mesh.ARRAY_VERTEX] = grown
	return out


## The surface with only its biggest pieces (by area) that hold at most [param share] of its
## triangles — at least the biggest one — as they are: a branch surface without its twigs. Pieces of
## about one size (within [constant SIZE_CLASSES_AN_OCTAVE]'s step) are kept spread evenly over the
## plant ([method _spread]), not in the order they were made: a curtain of like twigs thins all round.
func biggest(share: float) -> Array:
	var keeps: PackedByteArray = []
	keeps.resize(count)
	var kept: int = 0
	for piece: int in _biggest_order():
		if kept > 0 and kept + triangles[piece] > share * piece_of.size():
			break
		keeps[piece] = 1
		kept += triangles[piece]
	var picked: Dictionary = _picked_triangles(keeps)
	return _arrays_of(picked.used, picked.indices)


## The pieces in the order [method biggest] keeps them: by size class, bigger first, and in each
## class in [method _spread]'s order. Found once (each level and each step of a level's share keeps
## a number of the first).
func _biggest_order() -> Array[int]:
	if _biggest.size() == count:
		return _biggest
	var size_class: PackedInt32Array = []
	size_class.resize(count)
	for piece: int in count:
		size_class[piece] = floori(log(maxf(area[piece], 1e-12)) / log(2.0) * SIZE_CLASSES_AN_OCTAVE)
	_biggest.assign(range(count))
	var rank: PackedInt32Array = []
	rank.resize(count)
	var spread: Array[int] = _spread(_biggest)
	for k: int in spread.size():
		rank[spread[k]] = k
	_biggest.sort_custom(
		func(a: int, b: int) -> bool:
			return size_class[a] > size_class[b] or (size_class[a] == size_class[b] and rank[a] < rank[b])
	)
	return _biggest


## The kept pieces' triangles re-indexed over the vertices they use: [code]{"indices", "used" (the
## vertices, in their new order), "piece_of_vertex"}[/code]. A vertex two kept pieces share is used
## once for each (each card grows about its own centre).
func _picked_triangles(keeps: PackedByteArray) -> Dictionary:
	var indices: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
	var new_index: PackedInt32Array = []  # per vertex: its new number for the first piece that used it
	new_index.resize((arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size())
	new_index.fill(-1)
	var other_index: Dictionary = {}  # [a vertex, another piece] -> its new number for that piece
	var used: PackedInt32Array = []
	var piece_of_vertex: PackedInt32Array = []
	var out: PackedInt32Array = []
	for triangle: int in piece_of.size():
		var piece: int = piece_of[triangle]
		if not keeps[piece]:
			continue
		for corner: int in 3:
			var vertex: int = indices[3 * triangle + corner]
			if new_index[vertex] < 0:
				new_index[vertex] = used.size()
				used.append(vertex)
				piece_of_vertex.append(piece)
			elif piece_of_vertex[new_index[vertex]] != piece and not other_index.has([vertex, piece]):
				other_index[[vertex, piece]] = used.size()
				used.append(vertex)
				piece_of_vertex.append(piece)
			var number: int = new_index[vertex]
			if piece_of_vertex[number] != piece:
				number = other_index[[vertex, piece]]
			out.append(number)
	return {"indices": out, "used": used, "piece_of_vertex": piece_of_vertex}


## New arrays of the vertices [param used] (every kind the surface has) and [param indices].
func _arrays_of(used: PackedInt32Array, indices: PackedInt32Array) -> Array:
	var out: Array = []
	out.resize(Mesh.ARRAY_MAX)
	for kind: int in VERTEX_ARRAYS:
		if arrays[kind] != null:
			var width: int = 4 if kind == Mesh.ARRAY_TANGENT else 1
			var values: Variant = arrays[kind]
			var picked: Variant = values.duplicate()
			picked.resize(used.size() * width)
			for k: int in used.size():
				for part: int in width:
					picked[k * width + part] = values[used[k] * width + part]
			out[kind] = picked
	out[Mesh.ARRAY_INDEX] = indices
	return out


## Which pieces are kept when [param kept] cards are: every piece that is not a card, and the first
## [param kept] cards of [method _card_order].
func _chosen(kept: int) -> PackedByteArray:
	var keeps: PackedByteArray = []
	keeps.resize(count)
	keeps.fill(1)
	var order: Array[int] = _card_order()
	for k: int in range(kept, order.size()):
		keeps[order[k]] = 0
	return keeps


## The cards in the order they are kept ([method _spread]). Found once (every level and every step
## of the growth's search keeps a number of the first).
func _card_order() -> Array[int]:
	if _order.size() != cards.size():
		_order = _spread(Array(cards))
	return _order


## [param pieces] in the order of a curve through space (Morton's, over their centres), ranked by
## their place's bits reversed: any number of the first is spread evenly over the plant, and fewer
## of the first are always among more.
func _spread(pieces: Array) -> Array[int]:
	var out: Array[int] = []
	if pieces.is_empty():
		return out
	var box: AABB = AABB(centre[pieces[0]], Vector3.ZERO)
	for piece: int in pieces:
		box = box.expand(centre[piece])
	var codes: Dictionary = {}  # a piece -> its place on the curve, ties in the pieces' order
	for piece: int in pieces:
		var at: Vector3 = (centre[piece] - box.position) / box.size.max(Vector3.ONE * 1e-9)
		codes[piece] = _morton(at) * count + piece
	var along: Array[int] = []
	along.assign(pieces)
	along.sort_custom(func(a: int, b: int) -> bool: return codes[a] < codes[b])
	var bits: int = maxi(1, ceili(log(float(along.size())) / log(2.0)))
	var rank: Dictionary = {}
	for place: int in along.size():
		rank[along[place]] = _reversed(place, bits) * along.size() + place
	out = along.duplicate()
	out.sort_custom(func(a: int, b: int) -> bool: return rank[a] < rank[b])
	return out


## The Morton code of [param at] (each coordinate 0 to 1) on a grid of 1 024 a side.
static func _morton(at: Vector3) -> int:
	var code: int = 0
	for bit: int in 10:
		for axis: int in 3:
			var cell: int = clampi(int(at[axis] * 1024.0), 0, 1023)
			code |= ((cell >> bit) & 1) << (3 * bit + axis)
	return code


## [param value]'s lowest [param bits] bits in the reverse order.
static func _reversed(value: int, bits: int) -> int:
	var out: int = 0
	for bit: int in bits:
		out |= ((value >> bit) & 1) << (bits - 1 - bit)
	return out


## Joins the sets of triangles [param a] and [param b] are in (a forest of [param parent] links).
static func _join(parent: Array[int], a: int, b: int) -> void:
	var root_a: int = _root_of(parent, a)
	var root_b: int = _root_of(parent, b)
	if root_a != root_b:
		parent[maxi(root_a, root_b)] = mini(root_a, root_b)


## The first triangle of the set [param triangle] is in (halving the links on the way).
static func _root_of(parent: Array[int], triangle: int) -> int:
	while parent[triangle] != triangle:
		parent[triangle] = parent[parent[triangle]]
		triangle = parent[triangle]
	return triangle
