"""Robot-terms diff between the manifest's joint table and the new model."""
from __future__ import annotations

from dataclasses import replace

from rhi_gen.write.manifest import GroupRecord, JointRecord, Manifest, RobotRecord, TransmissionRecord
from rhi_gen.write.semantic_diff import diff_manifest, diff_robot


def J(index, name, lower=-1.0, upper=1.0, velocity=10.0, effort=20.0, type="revolute"):
    return JointRecord(index, name, type, lower, upper, velocity, effort)


def R(*joints, motor_count=4, float_type="float", urdf="u" * 64, yaml="y" * 64, key="acme/arm"):
    return RobotRecord(key, "robots/acme/arm.yaml", yaml, "robots/acme/arm.urdf", urdf, motor_count,
                       float_type, tuple(joints))


BASE = R(J(0, "hip"), J(1, "knee"), J(2, "ankle"), J(3, "wrist"))


def test_unchanged():
    d = diff_robot(BASE, BASE)
    assert d.status == "unchanged" and not d.stale and not d.robot_changed
    assert d.lines() == ["acme/arm: inputs unchanged"]


def test_rename_is_same_index_new_name_old_name_gone():
    new = R(J(0, "hip"), J(1, "knee_pitch"), J(2, "ankle"), J(3, "wrist"), urdf="v" * 64, yaml="z" * 64)
    d = diff_robot(BASE, new)
    assert d.renamed == ((1, "knee", "knee_pitch"),)
    assert not (d.added or d.removed or d.remapped or d.limits or d.types or d.motor_count or d.float_type)
    assert d.lines() == ["acme/arm: robots/acme/arm.yaml changed, robots/acme/arm.urdf changed",
                         "  renamed     joint 1: knee -> knee_pitch"]


def test_remap_is_same_name_new_index_and_a_swap_is_two_remaps():
    new = R(J(0, "hip"), J(1, "ankle"), J(2, "knee"), J(3, "wrist"), yaml="z" * 64)
    d = diff_robot(BASE, new)
    assert d.remapped == (("ankle", 2, 1), ("knee", 1, 2))
    assert not (d.renamed or d.added or d.removed)
    assert "  remapped    joint knee: index 1 -> 2" in d.lines()


def test_name_moving_into_another_slot_is_not_a_rename():
    # slot 1: knee -> ankle, but ankle existed (at 2): ankle is remapped, knee removed, slot 2 gets a new joint
    new = R(J(0, "hip"), J(1, "ankle"), J(2, "toe"), J(3, "wrist"), urdf="v" * 64)
    d = diff_robot(BASE, new)
    assert d.renamed == ()
    assert d.remapped == (("ankle", 2, 1),)
    assert [j.name for j in d.added] == ["toe"] and [j.name for j in d.removed] == ["knee"]


def test_added_removed_limits_type_motor_count_float_type():
    new = R(J(0, "hip", upper=1.25), J(1, "knee", type="continuous", lower=None, upper=None), J(2, "ankle"),
            J(4, "thumb", lower=-0.5, upper=0.5, velocity=2.0, effort=1.0),
            motor_count=5, float_type="double", urdf="v" * 64, yaml="z" * 64)
    d = diff_robot(BASE, new)
    assert [j.name for j in d.added] == ["thumb"] and [j.name for j in d.removed] == ["wrist"]
    assert d.limits == (("hip", 0, (("upper", 1.0, 1.25),)),
                        ("knee", 1, (("lower", -1.0, None), ("upper", 1.0, None))))
    assert d.types == (("knee", 1, "revolute", "continuous"),)
    assert d.motor_count == (4, 5) and d.float_type == ("float", "double")
    lines = d.lines()
    assert "  added       joint 4: thumb (revolute, lower -0.5, upper 0.5, velocity 2, effort 1)" in lines
    assert "  removed     joint 3: wrist" in lines
    assert "  limits      joint 0 hip: upper 1 -> 1.25" in lines
    assert "  limits      joint 1 knee: lower -1 -> none, upper 1 -> none" in lines
    assert "  type        joint 1 knee: revolute -> continuous" in lines
    assert "  motor_count 4 -> 5" in lines and "  float_type  float -> double" in lines


def test_rename_with_limit_change_reports_both_under_the_new_name():
    new = R(J(0, "hip"), J(1, "knee2", effort=30.0), J(2, "ankle"), J(3, "wrist"), urdf="v" * 64)
    d = diff_robot(BASE, new)
    assert d.renamed == ((1, "knee", "knee2"),)
    assert d.limits == (("knee2", 1, (("effort", 20.0, 30.0),)),)


def test_inputs_changed_without_robot_change_says_so():
    # The generator version is not a robot input: `check` reports it in its own line (test_reviewable_diffs).
    d = diff_robot(BASE, replace(BASE, yaml_sha256="z" * 64))
    assert d.stale and not d.robot_changed
    assert d.lines() == ["acme/arm: robots/acme/arm.yaml changed",
                         ("  no joint, limit, command mode, transmission, motor count or float type change (see "
                          "the file diff)")]


def test_format_1_yaml_fingerprints_are_not_compared():
    """Format 1 hashed the YAML bytes: the robot is stale once, and says why, instead of "changed"."""
    old = Manifest("0.1.0", {"acme/arm": BASE}, {}, format=1)
    [d] = diff_manifest(old, [replace(BASE, yaml_sha256="z" * 64)])
    assert d.stale and d.lines()[0] == ("acme/arm: robots/acme/arm.yaml was fingerprinted by an older rhi-gen "
                                        "(its bytes, not its content)")


def test_new_and_removed_robots():
    other = replace(BASE, key="acme/leg")
    diffs = diff_manifest(Manifest("0.1.0", {"acme/leg": other}, {}), [BASE], removed_keys=["acme/leg"])
    assert [(d.key, d.status) for d in diffs] == [("acme/arm", "new"), ("acme/leg", "removed")]
    assert diffs[0].lines() == [("acme/arm: new robot (4 joints, 4 motors, float; robots/acme/arm.yaml, "
                                 "robots/acme/arm.urdf)")]
    assert "robot removed" in diffs[1].lines()[0]
    assert [d.status for d in diff_manifest(None, [BASE])] == ["new"]


def test_transmission_changes_in_robot_terms():
    geared = replace(BASE, yaml_sha256="z" * 64, transmissions=(TransmissionRecord("knee", -1, 50.0, 0.0),),
                     coupled_groups=(GroupRecord("wrist", ("ankle", "wrist"), ((0.5, 0.5), (0.5, -0.5))),))
    d = diff_robot(BASE, geared)
    assert d.robot_changed
    assert d.lines()[1:] == ["  knee: transmission reduction 1 -> 50, direction +1 -> -1",
                             "  coupled group wrist: added (ankle, wrist), matrix [[0.5, 0.5], [0.5, -0.5]]"]
    back = diff_robot(geared, replace(
        BASE, yaml_sha256="w" * 64, transmissions=(TransmissionRecord("knee", -1, 50.0, 0.1),),
        coupled_groups=(GroupRecord("wrist", ("ankle", "wrist"), ((1.0, 0.0), (0.0, 2.0))),)))
    assert back.lines()[1:] == ["  knee: transmission offset 0 -> 0.1",
                                "  coupled group wrist: matrix [[0.5, 0.5], [0.5, -0.5]] -> [[1, 0], [0, 2]]"]
    gone = diff_robot(geared, replace(BASE, yaml_sha256="v" * 64))
    assert gone.lines()[1:] == ["  knee: transmission reduction 50 -> 1, direction -1 -> +1",
                                "  coupled group wrist: removed (ankle, wrist)"]


def test_a_manifest_without_transmissions_is_the_identity():
    assert not diff_robot(BASE, replace(BASE, transmissions=(TransmissionRecord("knee"),))).robot_changed


def test_command_mode_changes_in_robot_terms():
    """authority: upper_body makes the legs state-only: each is one `mode` line."""
    new = replace(BASE, yaml_sha256="z" * 64, command_modes=(("ankle", "state"), ("hip", "state"), ("knee", "state")))
    d = diff_robot(BASE, new)
    assert d.modes == (("hip", 0, "position", "state"), ("knee", 1, "position", "state"),
                       ("ankle", 2, "position", "state"))
    assert d.robot_changed
    assert d.lines()[1:] == ["  mode        joint 0 hip: position -> state",
                             "  mode        joint 1 knee: position -> state",
                             "  mode        joint 2 ankle: position -> state"]
    assert diff_robot(new, replace(BASE, yaml_sha256="w" * 64)).modes[0] == ("hip", 0, "state", "position")


def test_a_manifest_that_did_not_record_modes_tells_no_mode_change():
    old = replace(BASE, command_modes=None)  # written before rhi-gen recorded command modes
    new = replace(BASE, yaml_sha256="z" * 64, command_modes=(("wrist", "velocity"),))
    d = diff_robot(old, new)
    assert d.modes == () and not d.robot_changed
