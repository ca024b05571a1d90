package org.kheperasim.sim.gui.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kheperasim.sim.engine.robot.RobotFileWriter;
import org.kheperasim.sim.engine.robot.RobotType;
import org.kheperasim.sim.engine.robot.RobotTypes;

/**
 * The editor on the real robot files: what it saves reads back to the robot edited and re-saves
 * byte for byte; an edit the robot file's reader would refuse is refused in the editor with the
 * reader's reason (its file and line cut); a sensor removed closes up the channels so the file
 * still reads.
 */
class RobotFilesStoreTest {
    @TempDir
    Path dir;

    private final RobotFiles files = new RobotFiles();

    @Test
    void anEditedRobotSavesAndReadsBack() throws Exception {
        RobotDraft draft = new RobotDraft(files, RobotTypes.KHEPERA1, null);
        assertNull(draft.turnSensor(0, 60));
        assertNull(draft.setWheelBase(50));
        assertNull(draft.addSensor());
        assertNull(draft.setName("k1b"));
        Path f = dir.resolve("k.yaml");
        files.save(draft.type(), f);
        RobotType back = files.load(f);
        assertEquals(draft.type(), back, "a renamed robot too (its curve goes by its name)");
        assertEquals(RobotFileWriter.write(back), Files.readString(f), "re-saved byte for byte");
        assertTrue(Files.readString(f).contains("  wheel_base: 50\n"));
    }

    @Test
    void aRemovedSensorClosesUpTheChannels() {
        RobotDraft draft = new RobotDraft(files, RobotTypes.KHEPERA1, null);
        assertNull(draft.removeSensor(3));
        assertEquals(List.of(0, 1, 2, 3, 4, 5, 6), draft.type().sensors().stream().map(RobotType.Sensor::channel).toList());
        assertEquals("RIGHT_45", draft.type().sensor(3).name());
        assertEquals(3, draft.type().sensor(3).channel());
    }

    @Test
    void whatTheReaderRefusesTheEditorRefuses() {
        List<RobotType.Sensor> twice = List.of(new RobotType.Sensor("A", 0, 10, 0, 0), new RobotType.Sensor("B", 0, 0, 10, 90));
        RobotType k = RobotTypes.KHEPERA1;
        RobotType bad = new RobotType(k.name(), k.source(), k.body(), k.drive(), twice, k.proximity(), k.light(), k.turrets(),
                k.dialect());
        assertNull(RobotChecks.problem(bad), "the editor's own checks do not look at channels");
        assertEquals("channel 0 is used twice; number the sensors' channels 0 to 1, each once", files.problem(bad));
        RobotDraft draft = new RobotDraft(files, k, null);
        assertEquals(files.problem(bad), draft.apply(bad));
        assertEquals(k, draft.type());
    }

    @Test
    void theFromScratchTestRobotReads() {
        RobotType t = files.load(Path.of("src/test/resources/robots/roundbot.yaml"));
        assertEquals("roundbot", t.name());
        assertEquals(8, t.sensorCount());
        assertNull(RobotChecks.problem(t), "the editor takes it as it is");
        assertTrue(t.proximity().response() instanceof org.kheperasim.sim.engine.robot.Response.Table);
    }
}
