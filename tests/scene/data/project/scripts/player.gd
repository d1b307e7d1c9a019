extends CharacterBody3D

@export var speed := 5.0
@export var path_points: PackedVector3Array


func _on_timer_timeout() -> void:
	print("tick")
