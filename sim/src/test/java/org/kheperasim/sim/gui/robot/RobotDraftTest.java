package org.kheperasim.sim.gui.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The robot editor's model without a screen: the property sheet applies a good value, and refuses a
 * bad one with one line naming the field and the fix, leaving the robot as it was; sensors are
 * moved, turned, added and removed; a robot from scratch passes the checks.
 */
class RobotDraftTest {
    /** A store that only counts the checks asked of it (the robot file's reader is {@link RobotFilesTest}'s). */
    private static final class Store implements RobotFileStore {
        final List<RobotType> checked = new ArrayList<>();

        @Override
        public RobotType load(Path file) {
            throw new UnsupportedOperationException();
        }

        @Override
        public void save(RobotType type, Path file) {
            throw new UnsupportedOperationException();
        }

        @Override
        public String problem(RobotType type) {
            checked.add(type);
            return null;
        }
    }

    private final Store store = new Store();
    private final RobotDraft draft = new RobotDraft(store, RobotTypes.KHEPERA1, null);
    private final List<String> said = new ArrayList<>();
    private final RobotSheet sheet = new RobotSheet(draft, said::add);

    @Test
    void theSheetShowsTheNumbersAndAppliesAGoodValue() {
        assertEquals("53", sheet.getValueAt(sheet.row("wheel base, mm"), 1));
        assertEquals("27.5", sheet.getValueAt(sheet.row("body radius, mm"), 1));
        assertEquals("90", sheet.getValueAt(sheet.row("sensor 0 heading, degrees"), 1));
        assertEquals(RobotSheet.HEAD + RobotSheet.PER_SENSOR * 8, sheet.getRowCount());
        sheet.setValueAt("50", sheet.row("wheel base, mm"), 1);
        assertEquals(50, draft.type().drive().wheelBaseMm());
        assertTrue(draft.dirty());
        assertEquals(1, store.checked.size(), "the robot file's reader checked the edit");
        assertNull(said.get(said.size() - 1));
    }

    @Test
    void aBadValueIsRefusedInOneLineNamingTheFieldAndTheFix() {
        sheet.setValueAt("80", sheet.row("wheel base, mm"), 1);
        assertEquals("wheel base 80 mm is wider than the body (55 mm across); give at most 55 mm, or a larger body radius",
                said.get(0));
        sheet.setValueAt("abc", sheet.row("wheel base, mm"), 1);
        assertEquals("wheel base 'abc' is not a number; give mm, e.g. 53", said.get(1));
        sheet.setValueAt("2", sheet.row("body radius, mm"), 1);
        assertEquals("body radius 2 mm is out of range; give 5 to 500 mm", said.get(2));
        sheet.setValueAt("1.5", sheet.row("max speed, units"), 1);
        assertEquals("max speed '1.5' is not a number; give a whole number of speed units, e.g. 127", said.get(3));
        sheet.setValueAt("LEFT_45", sheet.row("sensor 0 name"), 1);
        assertEquals("sensor name 'LEFT_45' is used twice (sensors 0 and 1); give each sensor its own name", said.get(4));
        sheet.setValueAt("40", sheet.row("sensor 2 x (forward), mm"), 1);
        assertEquals("sensor 2 (FRONT_LEFT) at (40, 6) mm is 40.45 mm from the centre, off the body (radius 27.5 mm);"
                + " mount it within the body", said.get(5));
        sheet.setValueAt("10", sheet.row("body radius, mm"), 1);
        assertTrue(said.get(6).startsWith("wheel base 53 mm is wider than the body (20 mm across)"), said.get(6));
        assertEquals(RobotTypes.KHEPERA1, draft.type(), "nothing changed");
        assertTrue(!draft.dirty());
        for (String s : said) {
            assertTrue(!s.contains("\n"), s);
        }
    }

    @Test
    void sensorsAreMovedTurnedAddedAndRemoved() {
        assertNull(draft.turnSensor(0, 420));
        assertEquals(60, draft.type().sensor(0).headingDeg());
        assertNull(draft.turnSensor(0, -190));
        assertEquals(170, draft.type().sensor(0).headingDeg());
        assertNull(draft.moveSensor(1, 20, -5.5));
        assertEquals(-5.5, draft.type().sensor(1).yMm());
        assertNull(draft.addSensor());
        assertEquals(9, draft.type().sensorCount());
        assertEquals(8, draft.selected(), "the new sensor is chosen");
        assertEquals("S8", draft.type().sensor(8).name());
        assertEquals(8, draft.type().sensor(8).channel());
        assertNull(draft.removeSensor(3));
        assertEquals(8, draft.type().sensorCount());
        assertEquals("RIGHT_45", draft.type().sensor(3).name());
    }

    @Test
    void theLastSensorStays() {
        RobotDraft one = new RobotDraft(store, NewRobot.design("one", 20, 30, 8, 1, RobotTypes.KHEPERA1), null);
        assertEquals("the robot's only sensor cannot go; a robot has one sensor at least", one.removeSensor(0));
    }

    @Test
    void aRobotFromScratchPassesTheChecks() {
        RobotType tri = NewRobot.design("tri", 30, 45, 10, 3, RobotTypes.KHEPERA1);
        assertNull(RobotChecks.problem(tri));
        assertEquals(3, tri.sensorCount());
        assertEquals(List.of(90.0, 0.0, -90.0), tri.sensors().stream().map(RobotType.Sensor::headingDeg).toList());
        assertEquals(27, tri.sensor(0).yMm(), "on the left edge, 0.9 of the radius out");
        RobotType eight = NewRobot.design("eight", 35, 60, 8, 8, RobotTypes.KHEPERA1);
        assertNull(RobotChecks.problem(eight));
        assertEquals(180, eight.sensor(6).headingDeg());
        assertTrue(eight.sensor(6).yMm() < 0 && eight.sensor(7).yMm() > 0, "the back pair right then left, as the Khepera's");
        assertTrue(eight.turrets().isEmpty());
    }
}
