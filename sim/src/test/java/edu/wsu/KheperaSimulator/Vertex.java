package edu.wsu.KheperaSimulator;

import java.awt.Color;
import java.awt.Image;
import java.io.Serializable;

/**
 * A stand-in with the serialized form of the WSU simulator's Vertex (the facts of wsu-compat.md:
 * name, serialVersionUID, fields and their types), so that a test can let the JDK's own
 * ObjectOutputStream write a world file and check that the reader agrees with the test's writer.
 * The reader never loads this class.
 */
public class Vertex implements Serializable {
    private static final long serialVersionUID = -3311203242241057476L;

    int id;
    int objType;
    int oldx;
    int oldy;
    float theta;
    int xPos;
    int yPos;
    Image robotI;
    Color vertexColor;

    public Vertex(int id, int objType, int x, int y, float theta, Color colour) {
        this.id = id;
        this.objType = objType;
        this.oldx = x;
        this.oldy = y;
        this.theta = theta;
        this.xPos = x;
        this.yPos = y;
        this.vertexColor = colour;
    }
}
