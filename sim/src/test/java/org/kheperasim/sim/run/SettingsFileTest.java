package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kheperasim.sim.engine.model.Settings;

class SettingsFileTest {

    @ParameterizedTest
    @ValueSource(strings = {"0x1p10", "1d", "2f", "NaN", "Infinity", "1_0", "+-1", "1e", "", "١"})
    void numbersArePlainDecimals(String value) {
        SettingsFileException e = assertThrows(SettingsFileException.class,
                () -> SettingsFile.parse("# mine\nlink.baud=" + value + "\n", "mine.settings"));
        assertEquals(2, e.line());
        assertTrue(e.getMessage().startsWith("mine.settings:2: setting link.baud=" + value + ": not a decimal number"),
                e.getMessage());
    }

    @Test
    void decimalsInEveryFormReadAndWriteBack() {
        Settings s = SettingsFile.parse("\uFEFFprox.3.gain=1.5e-1\nnoise.reading = .5\nlink.baud=+9600\n", "ok.settings");
        assertEquals(0.15, s.number("prox.3.gain"), 1e-12);
        assertEquals(0.5, s.number("noise.reading"));
        assertEquals(s, SettingsFile.parse(SettingsFile.write(s), "again"));
    }

    @Test
    void aFileThatIsNotUtf8OrTooLargeIsRefusedAsSuch(@TempDir Path dir) throws IOException {
        Path latin = dir.resolve("latin.settings");
        Files.write(latin, new byte[] {'#', ' ', (byte) 0xE9, '\n'});
        SettingsFileException e = assertThrows(SettingsFileException.class, () -> SettingsFile.load(latin));
        assertTrue(e.getMessage().startsWith(latin + ":1: byte 0xE9 at column 3 is not UTF-8 text"), e.getMessage());
        Path big = dir.resolve("big.settings");
        Files.writeString(big, "#".repeat((int) SettingsFile.MAX_FILE_BYTES + 1));
        e = assertThrows(SettingsFileException.class, () -> SettingsFile.load(big));
        assertEquals(0, e.line());
        assertTrue(e.getMessage().contains("larger than 1 MiB, the limit for settings files"), e.getMessage());
    }
}
