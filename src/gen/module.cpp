// module placeholder; replaced by real sources
