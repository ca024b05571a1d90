package org.kheperasim.sim.run;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.kheperasim.link.fuzz.Fuzz;
import org.kheperasim.link.fuzz.Mutations;
import org.kheperasim.sim.engine.model.Settings;

/** Whatever the text, a settings file reads and writes back the same, or the error names its line. */
@Tag("properties")
@Timeout(value = 300, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SettingsFilePropertiesTest {

    private static final List<String> KEYS = new ArrayList<>(Settings.catalogue().keySet());
    private static final List<String> VALUES = List.of("true", "false", "khepera1", "khepera2", "TRUE", "yes", "0x1p10",
            "1e2", "  7 ", "1d", "-0", "38400", "300", "1000000", "1000001", "events", "tick");

    static String input(SplittableRandom r) {
        StringBuilder b = new StringBuilder();
        if (r.nextBoolean()) {
            b.append("# khepera-sim settings\n");
        }
        for (int i = 0, n = r.nextInt(8); i < n; i++) {
            String key = r.nextInt(20) == 0 ? Mutations.pick(r, List.of("prox.9.gain", "link", "", "=", "noise..reading"))
                    : Mutations.pick(r, KEYS);
            String value = r.nextInt(3) == 0 ? Mutations.pick(r, VALUES) : Mutations.number(r, -1, 2);
            b.append(key).append(r.nextInt(10) == 0 ? " = " : "=").append(value).append('\n');
        }
        String text = b.toString();
        return r.nextInt(3) == 0 ? Mutations.damage(r, text, List.of("=", "#", "link.baud", "prox.3.gain=1"), 3) : text;
    }

    static void readsOrNamesTheLine(String text) {
        Settings s;
        try {
            s = SettingsFile.parse(text, "fuzz.settings");
        } catch (SettingsFileException e) {
            int lines = text.split("\\R", -1).length;
            assertTrue(e.line() >= 1 && e.line() <= lines, "line " + e.line() + " of " + lines + ": " + e.getMessage());
            assertTrue(e.getMessage().startsWith("fuzz.settings:" + e.line() + ": "), e.getMessage());
            return;
        }
        assertEquals(s, SettingsFile.parse(SettingsFile.write(s), "again.settings"));
        for (String key : s.overrides().keySet()) {
            String raw = s.raw(key);
            assertTrue(!raw.contains("x") || raw.startsWith("khepera"), key + "=" + raw + " is a plain value");
        }
    }

    @Test
    void everyTextIsSettingsThatRoundTripOrAnErrorNamingItsLine() {
        Fuzz.checkText("settings file", 3000, SettingsFilePropertiesTest::input, SettingsFilePropertiesTest::readsOrNamesTheLine);
    }
}
