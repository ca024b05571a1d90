package org.kheperasim.sim.testkit;

import java.nio.file.Path;
import java.util.SortedMap;
import org.kheperasim.sim.engine.model.Settings;
import org.kheperasim.sim.run.SettingsFile;

/** A run's or a robot's settings ({@code --set key=value}), immutable. */
public final class KitSettings {
    final Settings settings;

    KitSettings(Settings settings) {
        this.settings = settings;
    }

    /** @return the defaults */
    public static KitSettings defaults() {
        return new KitSettings(Settings.defaults());
    }

    /**
     * @param file a settings file ({@code key = value} lines, as the window saves them)
     * @return its settings
     */
    public static KitSettings load(Path file) {
        return new KitSettings(SettingsFile.load(file));
    }

    /** @param key a setting's name @return true when it is one setting for the whole run, not per robot */
    public static boolean wholeRun(String key) {
        return Settings.wholeRun(key);
    }

    /**
     * @param key a setting's name
     * @param value its value
     * @return these settings with one changed
     * @throws IllegalArgumentException naming the setting and its allowed values when either is wrong
     */
    public KitSettings with(String key, String value) {
        return new KitSettings(settings.with(key, value));
    }

    /** @param assignment {@code key=value} @return these settings with one changed */
    public KitSettings with(String assignment) {
        return new KitSettings(settings.with(assignment));
    }

    /** @return the settings that differ from the defaults, by name */
    public SortedMap<String, String> overrides() {
        return settings.overrides();
    }

    /** @return the settings as a trace's header and the run's summary describe them ({@code defaults}, or pairs) */
    public String describe() {
        return settings.describe();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof KitSettings k && k.settings.equals(settings);
    }

    @Override
    public int hashCode() {
        return settings.hashCode();
    }

    @Override
    public String toString() {
        return settings.toString();
    }
}
