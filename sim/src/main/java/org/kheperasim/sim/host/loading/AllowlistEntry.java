package org.kheperasim.sim.host.loading;

import java.util.List;

/**
 * One entry of the controller allowlist (the file's format is described at its top): the classes it
 * names, the members of theirs it allows (or, in the refused group, the uses it explains), and why.
 *
 * @param classes the classes named
 * @param members the members named; empty: the type alone
 * @param reason why it is safe (allowed groups), or what a refusal says (the refused group)
 * @param group the group the entry is in
 * @param line the entry's first line in the file
 */
record AllowlistEntry(ClassPattern classes, List<MemberItem> members, String reason, Group group, int line) {

    /** The kind of a group of entries. */
    enum Kind {
        /** Members controller code may use. */
        ALLOWED,
        /** Members that may only be named as the bootstrap method of an invokedynamic or dynamic constant. */
        BOOTSTRAP,
        /** Not allowed: the reason an error gives for a use refused. */
        REFUSED
    }

    /** A heading of the file, and what its entries are. */
    record Group(String title, Kind kind) {
    }

    /**
     * Which classes an entry names.
     *
     * @param text as written in the file (one of the names of a brace list)
     * @param kind how {@code value} is compared
     * @param value the binary name, package (with its final dot) or prefix
     * @param mustExtend a class the named classes must be subclasses of, or null
     */
    record ClassPattern(String text, PatternKind kind, String value, String mustExtend) {
        /** @return whether the pattern names {@code binaryName}, before the subclass condition */
        boolean names(String binaryName) {
            return switch (kind) {
                case EXACT -> binaryName.equals(value);
                case PACKAGE -> binaryName.startsWith(value) && binaryName.indexOf('.', value.length()) < 0;
                case SUBPACKAGES, PREFIX -> binaryName.startsWith(value);
            };
        }

        /** @return how specific the pattern is: an exact name beats every pattern, a longer pattern a shorter one */
        int rank() {
            return kind == PatternKind.EXACT ? Integer.MAX_VALUE : value.length();
        }
    }

    /** How a class pattern compares names. */
    enum PatternKind {
        /** One class. */
        EXACT,
        /** The classes of one package ({@code pkg.*}). */
        PACKAGE,
        /** The classes of a package and its subpackages ({@code pkg.**}). */
        SUBPACKAGES,
        /** Names that start with the value ({@code Prefix*}). */
        PREFIX
    }

    /**
     * One item of an entry's member list.
     *
     * @param exclude written after a minus: it excludes
     * @param name the member's name ({@code <init>} for a constructor), a prefix, or {@code *} for all
     * @param prefix {@code name} is a prefix ({@code name*})
     * @param parameters the parameter types of one overload (binary names, primitives, arrays as
     *     {@code int[]}), or null for every overload
     */
    record MemberItem(boolean exclude, String name, boolean prefix, List<String> parameters) {
        /** The rank of an item: the more specific one decides. */
        int rank() {
            if (parameters != null) {
                return 3;
            }
            if (name.equals("*")) {
                return 0;
            }
            return prefix ? 1 : 2;
        }

        /**
         * @param member the member's name
         * @param memberParameters its parameter types, or null for a field
         */
        boolean matches(String member, List<String> memberParameters) {
            if (parameters != null) {
                return memberParameters != null && name.equals(member) && parameters.equals(memberParameters);
            }
            if (name.equals("*")) {
                return true;
            }
            return prefix ? member.startsWith(name) : member.equals(name);
        }
    }

    /**
     * @param member the member's name ({@code <init>} for a constructor)
     * @param parameters its parameter types, or null for a field
     * @return whether the entry's member list allows it: the most specific matching item decides, an
     *     exclusion winning at equal rank
     */
    boolean allows(String member, List<String> parameters) {
        int best = -1;
        boolean allowed = false;
        for (MemberItem item : members) {
            if (!item.matches(member, parameters)) {
                continue;
            }
            int rank = item.rank();
            if (rank > best) {
                best = rank;
                allowed = !item.exclude();
            } else if (rank == best && item.exclude()) {
                allowed = false;
            }
        }
        return allowed;
    }

    /** @return whether the entry (a refused one) speaks of this use: it names no member, or one that matches */
    boolean mentions(String member, List<String> parameters) {
        if (members.isEmpty()) {
            return true;
        }
        return member != null && members.stream().anyMatch(i -> i.matches(member, parameters));
    }
}
